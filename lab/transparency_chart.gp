# Draws transparency.svg from transparency-lab's CSVs:
#   build/release/lab/transparency-lab --out=doc/lab && gnuplot -e "dir='doc/lab'" lab/transparency_chart.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 1100,520 dynamic enhanced font "sans,12" background "white"
set output sprintf("%s/transparency.svg", dir)
set multiplot layout 1,2 title "Transparency: exact sorting against the cheap methods, and what exactness costs" font ",14"
set grid lw 0.5 lc "#dddddd"
set key top right box opaque
# Left: the three methods on the crossing squares, error against time.
set title "Three crossing squares, 512 x 512, one sample"
set xlabel "CPU ms a frame (cheap methods: every layer shaded, far to near, plus their compositing)"
set ylabel "error in linear light against the exact frame"
set xrange [0:*]
set offsets 0, graph 0.35, 0, 0
set yrange [0:0.45]
file = sprintf("%s/transparency.csv", dir)
plot file using 2:3 with points pt 7 ps 1.6 lc "#1f77b4" title "mean", \
     file using 2:4 with points pt 5 ps 1.3 lc "#d62728" title "worst", \
     file using 2:4:(stringcolumn(1)) with labels left offset 1,0.6 font ",10" noenhanced notitle
# Right: the blended frame's time over the opaque frame's, by layers over every pixel.
set title "Lit layers over every pixel, 800 x 600, one thread"
set xlabel "layers over every pixel"
set ylabel "frame / the same layers opaque as drawn (process CPU time)"
set offsets 0, 0, 0, 0
set xrange [0.5:8.5]
set yrange [0:6.5]
set xtics 1
set key top left box opaque font ",10"
cost = sprintf("%s/transparency-cost.csv", dir)
plot cost using ($1 == 1 && $2 == 1 ? $3 : 1/0):10 with linespoints lw 2 pt 7 lc "#1f77b4" title "exact, 1 sample", \
     cost using ($1 == 4 && $2 == 1 ? $3 : 1/0):10 with linespoints lw 2 pt 5 lc "#ff7f0e" title "exact, 4 samples", \
     cost using ($1 == 1 && $2 == 1 ? $3 : 1/0):($11 / $8) with linespoints lw 1 dt 3 pt 6 lc "#1f77b4" \
          title "every layer shaded opaque, 1 sample", \
     cost using ($1 == 4 && $2 == 1 ? $3 : 1/0):($11 / $8) with linespoints lw 1 dt 3 pt 4 lc "#ff7f0e" \
          title "every layer shaded opaque, 4 samples", \
     1.5 with lines dt 2 lw 2 lc "#2ca02c" title "the issue's target, 1.5"
unset multiplot
