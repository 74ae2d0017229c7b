# Draws colour.svg from colour-lab's CSV: gnuplot -e "dir='doc/lab'" lab/colour_chart.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 900,520 dynamic enhanced font "sans,12" background "white"
set output sprintf("%s/colour.svg", dir)
set grid lw 0.5 lc "#dddddd"
set title "Linear light to 8-bit sRGB: every float in [0, 1] against the definition" font ",14"
set xlabel "nanoseconds per channel (median of 11 passes, lower is better)"
set ylabel "floats encoded to another byte than the definition's, + 1"
set logscale y
set xrange [0:*]
set yrange [0.5:1e9]
set key top right box opaque
set offsets graph 0.05, graph 0.25, 0, 0
file = sprintf("%s/colour.csv", dir)
plot file using 4:($2 + 1) every ::1 with points pt 7 ps 1.5 lc "#3366cc" title "method", \
     file using 4:($7 == 1 ? $2 + 1 : 1/0) every ::1 with points pt 5 ps 2.4 lc "#d62728" title "product", \
     file using 4:($2 + 1):(stringcolumn(1)) every ::1 with labels offset char 0, char 1.2 font ",10" notitle
