# Draws material.svg from material-lab's CSV:
#   build/release/bin/material-lab --out=doc/lab && gnuplot -e "dir='doc/lab'" lab/material_chart.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 900,520 dynamic enhanced font "sans,12" background "white"
set grid lw 0.5 lc "#dddddd"
set key top right box opaque
set output sprintf("%s/material.svg", dir)
set title "White furnace: each environment approximation's error against its cost" font ",14"
set xlabel "nanoseconds per pixel (lookup or fit)"
set ylabel "error, % of the energy received (lower is better)"
set logscale y
file = sprintf("%s/material.csv", dir)
plot file using 2:3 with points pt 7 ps 1.5 lc "#1f77b4" title "mean", \
     file using 2:4 with points pt 5 ps 1.2 lc "#d62728" title "worst", \
     file using 2:4:(sprintf("%s", stringcolumn(1))) with labels left offset 1,0 font ",9" notitle
