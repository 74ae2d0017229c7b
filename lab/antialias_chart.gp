# Draws antialias.svg from antialias-lab's CSV: gnuplot -e "dir='doc/lab'" lab/antialias_chart.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 900,560 dynamic enhanced font "sans,12" background "white"
set grid lw 0.5 lc "#dddddd"
set key top right box opaque autotitle columnhead
set output sprintf("%s/antialias.svg", dir)
set title "Anti-aliasing: coverage error against the exact pixel area, and the cost of a frame" font ",14"
set xlabel "milliseconds per 800 x 600 frame of the diary's torus, one thread (lower is better)"
set ylabel "mean |coverage error| over edge pixels (lower is better)"
set logscale xy
set xrange [3:300]
set yrange [0.001:1]
file = sprintf("%s/antialias-time.csv", dir)
# Columns: samples, torus ms, ptah ms, the same two supersampled, then each case's mean error.
plot for [k=6:11] file using 2:k with linespoints lw 2 pt (k - 1) ps 1.2 title columnheader(k), \
     file using 4:7 with linespoints lw 2 dt 2 lc "#777777" pt 4 ps 1.2 title "triangles 8 px, supersampled", \
     file using 2:7:(sprintf("%d", $1)) with labels offset char 0, char 1.2 font ",10" notitle
