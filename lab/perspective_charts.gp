# Draws interpolation.svg and depth-perspective.svg from perspective-lab's CSV:
#   gnuplot -e "dir='doc/lab'" lab/perspective_charts.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 900,520 dynamic enhanced font "sans,12" background "white"
set grid lw 0.5 lc "#dddddd"
set key top right box opaque

set output sprintf("%s/interpolation.svg", dir)
set title "Interpolation on a floor seen at grazing angles: error against time" font ",14"
set xlabel "milliseconds per 800 x 600 frame (median of 31, lower is better)"
set ylabel "worst texture-coordinate error, texels (256 per unit)"
set logscale y
file = sprintf("%s/interpolation.csv", dir)
plot file using (strcol(1) eq "affine" && $3 == 5 ? $6 : 1/0):4 every ::1 with linespoints pt 7 lc "#3366cc" title "affine, 5 deg down, 1..64 cells", \
     file using (strcol(1) eq "affine" && $3 == 20 ? $6 : 1/0):4 every ::1 with linespoints pt 9 lc "#2ca02c" title "affine, 20 deg down, 1..64 cells", \
     file using (strcol(1) eq "perspective" ? $6 : 1/0):($4 + 1e-3) every ::1 with points pt 5 ps 1.6 lc "#d62728" title "through 1/w in double (product), 1 and 64 cells", \
     file using (strcol(1) eq "perspective in float" ? $6 : 1/0):($4 + 1e-3) every ::1 with points pt 4 ps 1.6 lc "#9467bd" title "through 1/w in float, 1 and 64 cells", \
     file using (strcol(1) eq "affine" ? $6 : 1/0):4:(sprintf("%d", $2)) every ::1 with labels offset char 0.8, char 0.6 font ",9" notitle

set output sprintf("%s/depth-perspective.svg", dir)
set title "Two floors 1e-5 apart: pixels where the depth buffer puts the far one in front" font ",14"
set xlabel "far / near"
set ylabel "share of pixels wrong"
set logscale x
unset logscale y
set yrange [-0.03:1.03]
set key top left box opaque
file = sprintf("%s/depth-perspective.csv", dir)
plot for [k=2:6] file using 1:k every ::1 with linespoints lw 2 pt (k + 3) ps 1.2 title columnheader(k)
