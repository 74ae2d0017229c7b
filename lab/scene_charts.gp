# Draws the scene lab's charts from scene-lab's CSV: gnuplot -e "dir='doc/lab'" lab/scene_charts.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 1100,520 dynamic enhanced font "sans,12" background "white"
set grid lw 0.5 lc "#dddddd"
shading = sprintf("%s/shading.csv", dir)
front = sprintf("%s/shading-pareto.csv", dir)
# A zero error cannot sit on a log axis: it is drawn at this floor, labelled "0".
floor = 0.3
shown(e) = e < floor ? floor : e
is(shape, method) = strcol(1) eq shape && strcol(4) eq method

# 1. Tessellation: how far the outline strays, and what each level costs.
set output sprintf("%s/tessellation.svg", dir)
set multiplot layout 1,2 title "Tessellation: outline error and time by level (800 x 600; sphere radius 210 px, torus at 0.8)" font ",14"
set logscale xy
set xlabel "facets"
set ylabel "outline error (px): farthest mesh point from the true surface, on screen"
set key top right box opaque
set arrow 1 from graph 0, first 0.5 to graph 1, first 0.5 nohead lc "#d62728" dt 2
set label 1 "half a pixel" at graph 0.02, first 0.6 tc "#d62728"
plot for [s in "sphere torus"] shading using 3:(is(s, "phong") ? $5 : 1/0) every ::1 with linespoints lw 2 pt 7 title s, \
     for [s in "sphere torus"] shading using 3:(is(s, "phong") ? $5 : 1/0):(sprintf("%d", $2)) every ::1 with labels offset char 0.8, char 0.8 font ",9" notitle
unset arrow 1
unset label 1
set ylabel "ms per frame, Phong shading (median)"
set key top left
plot for [s in "sphere torus"] shading using 3:(is(s, "phong") ? $10 : 1/0) every ::1 with linespoints lw 2 pt 7 title s, \
     for [s in "sphere torus"] shading using 3:(is(s, "flat") ? $10 : 1/0) every ::1 with linespoints lw 1 dt 2 pt 6 title s." (flat)"
unset multiplot

# 2. Shading: error against time for every level and method; the front, the diary and auto.
set output sprintf("%s/shading.svg", dir)
set multiplot layout 1,2 title "Shading: largest error inside the outline against time, every level (numbers) and method" font ",14"
set xlabel "ms per frame (median, lower is better)"
set ylabel "largest error, 8-bit levels vs the ray-cast surface"
set ytics add ("0" floor)
set key top right box opaque font ",10"
do for [s in "sphere torus"] {
    set title s
    set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead lc "#d62728" dt 2
    plot front using 4:(strcol(1) eq s ? shown($5) : 1/0) every ::1 with lines lw 2 lc "#999999" dt 2 title "Pareto front", \
         for [m in "flat gouraud phong"] shading using 10:(is(s, m) ? shown($8) : 1/0) every ::1 with points pt 7 ps 1.1 title m, \
         shading using 10:(strcol(1) eq s && $14 == 1 ? shown($8) : 1/0) every ::1 with points pt 4 ps 2.6 lw 2 lc "#000000" title "diary", \
         shading using 10:(strcol(1) eq s && $15 == 1 ? shown($8) : 1/0) every ::1 with points pt 3 ps 3 lw 2 lc "#d62728" title "--detail auto", \
         shading using 10:(strcol(1) eq s ? shown($8) : 1/0):(sprintf("%d", $2)) every ::1 with labels offset char 0.7, char 0.6 font ",8" notitle
}
unset multiplot
unset arrow 1
unset ytics
set ytics

# 3. Depth formats: wrong-surface pixels on near-coplanar and crossing planes. Rows come in
# threes (float32, fixed24, fixed16) per case: six crossing cases, then six gaps.
depth = sprintf("%s/depth.csv", dir)
formats = "float32 fixed24 fixed16"
do for [k=1:3] {
    stats depth using (strcol(3) eq word(formats, k) ? $6 : 1/0) every ::1 nooutput
    eval sprintf("ms%d = %.3f", k, STATS_median)
}
ms(k) = k == 1 ? ms1 : k == 2 ? ms2 : ms3
set output sprintf("%s/depth.svg", dir)
set multiplot layout 1,2 title "Depth formats: pixels showing the wrong surface (of 72,000 compared); key: median ms to draw a pair" font ",14"
set logscale xy
set ylabel "wrong pixels + 1"
set key top left box opaque
set title "parallel planes slanted 60 degrees, the far one drawn last"
set xlabel "gap between the planes (world units; the view spans 2)"
set xrange [0.02:5e-8]
plot for [k=1:3] depth using 2:($4 + 1) every 3::(18 + k) with linespoints lw 2 pt 7 title sprintf("%s (%.2f ms)", word(formats, k), ms(k))
set title "planes crossing at an angle"
set xlabel "angle between the planes (degrees)"
set xrange [20:5e-5]
plot for [k=1:3] depth using 2:($4 + 1) every 3::k::18 with linespoints lw 2 pt 7 title sprintf("%s (%.2f ms)", word(formats, k), ms(k))
unset multiplot
