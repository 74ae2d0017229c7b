# Draws texture-filtering.svg from texture-lab's CSV:
#   gnuplot -e "dir='doc/lab'" lab/texture_chart.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 900,520 dynamic enhanced font "sans,12" background "white"
set grid lw 0.5 lc "#dddddd"
set key top right box opaque
set output sprintf("%s/texture-filtering.svg", dir)
set title "Checkerboard floor to the horizon: error against a 256-ray reference, by image band" font ",14"
set xlabel "image band, 1 = top (sky; the horizon lies in band 5) to 12 = bottom (nearest the eye)"
set ylabel "RMS error, sRGB levels (lower is better)"
set xtics 1
file = sprintf("%s/texture-filtering.csv", dir)
plot for [k=2:4] file using 1:k with linespoints lw 2 pt (k + 4) ps 1.2 title columnheader(k)
