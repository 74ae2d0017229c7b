# Draws gl-detail.svg, gl-resolution.svg and gl-ratio.svg from tools/bench-gl.sh's gl.csv.
if (!exists("dir")) dir = "doc/bench"
set datafile separator ","
set terminal svg size 1100,560 dynamic enhanced font "sans,12" background "white"
set grid lw 0.5 lc "#dddddd"
set key top right box opaque
set logscale xy
set ylabel "frames per second (median, higher is better)"
file = sprintf("%s/gl.csv", dir)
set output sprintf("%s/gl-detail.svg", dir)
set title "Tumbling torus at 800 x 600 by facet count: raster against llvmpipe" font ",14"
set xlabel "facets"
plot file using ($2 == 800 && strcol(1)[1:5] eq "torus" && strstrt(strcol(1), " ") == 0 ? $4 : 1/0):5 every ::1 with linespoints lw 2 pt 7 lc "#d62728" title "raster, 1 thread", \
     file using ($2 == 800 && strcol(1)[1:5] eq "torus" && strstrt(strcol(1), " ") == 0 ? $4 : 1/0):6 every ::1 with linespoints lw 2 pt 5 lc "#ff9896" title "raster, all cores", \
     file using ($2 == 800 && strcol(1)[1:5] eq "torus" && strstrt(strcol(1), " ") == 0 ? $4 : 1/0):7 every ::1 with linespoints lw 2 pt 9 lc "#1f77b4" title "llvmpipe, 1 thread", \
     file using ($2 == 800 && strcol(1)[1:5] eq "torus" && strstrt(strcol(1), " ") == 0 ? $4 : 1/0):8 every ::1 with linespoints lw 2 pt 11 lc "#aec7e8" title "llvmpipe, default threads"
set output sprintf("%s/gl-resolution.svg", dir)
set title "Tumbling torus(24, 16) by image size: raster against llvmpipe" font ",14"
set xlabel "pixels"
plot file using (strcol(1) eq "torus-1" ? $2 * $3 : 1/0):5 every ::1 with linespoints lw 2 pt 7 lc "#d62728" title "raster, 1 thread", \
     file using (strcol(1) eq "torus-1" ? $2 * $3 : 1/0):6 every ::1 with linespoints lw 2 pt 5 lc "#ff9896" title "raster, all cores", \
     file using (strcol(1) eq "torus-1" ? $2 * $3 : 1/0):7 every ::1 with linespoints lw 2 pt 9 lc "#1f77b4" title "llvmpipe, 1 thread", \
     file using (strcol(1) eq "torus-1" ? $2 * $3 : 1/0):8 every ::1 with linespoints lw 2 pt 11 lc "#aec7e8" title "llvmpipe, default threads"
unset logscale
set output sprintf("%s/gl-ratio.svg", dir)
set title "raster's frames per second over llvmpipe's, every case (above the line: twice as fast)" font ",14"
set xlabel ""
set ylabel "fps ratio, raster / llvmpipe"
set style data histograms
set style histogram errorbars gap 1 lw 1
set style fill solid 0.9 border -1
set boxwidth 0.9
set yrange [0:*]
set xtics rotate by -30 left
set rmargin 16  # room for the last rotated label
set key top left box opaque
plot file using 9:12:13:xticlabels(sprintf("%s %sx%s", strcol(1), strcol(2), strcol(3))) every ::1 lc "#d62728" title "1 thread each (bar: median round; whisker: range)", \
     file using 10:14:15 every ::1 lc "#ff9896" title "all cores each", \
     2 with lines dt 2 lw 2 lc "#444444" title "target, 1 thread"
