# Draws encode.svg from encode-lab's CSV:  gnuplot -e "dir='doc/lab'" lab/encode_chart.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 900,560 dynamic enhanced font "sans,12" background "white"
set grid lw 0.5 lc "#dddddd"
set key top right box opaque
set output sprintf("%s/encode.svg", dir)
set title "animated-cube's 360 frames at 800 x 600: encode time against file size" font ",14"
set xlabel "seconds to encode all frames (median, lower is better)"
set ylabel "file size, kB"
set logscale x
file = sprintf("%s/encode.csv", dir)
plot file using (strcol(2) eq "anim" ? $3 : 1/0):($6/1000) every ::1 with points pt 7 ps 1.4 lc "#3366cc" title "libwebp anim encoder (fast, default, max)", \
     file using (strcol(2) eq "parallel" ? $3 : 1/0):($6/1000) every ::1 with points pt 5 ps 1.1 lc "#2ca02c" title "parallel: changed rectangles on a pool", \
     file using ($7 == 1 ? $3 : 1/0):($6/1000) every ::1 with points pt 6 ps 2.4 lw 2 lc "#d62728" title "Pareto front", \
     file using ($7 == 1 ? $3 : 1/0):($6/1000):1 every ::1 with labels offset char 1, char 0.7 font ",9" notitle
