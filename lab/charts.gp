# Draws the lab's charts from the CSV tables raster-lab wrote: gnuplot -e "dir='doc/lab'" lab/charts.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
set terminal svg size 900,560 dynamic enhanced font "sans,12" background "white"
set grid lw 0.5 lc "#dddddd"
set key top right box opaque

# Zero error cannot sit on a log axis: exact methods are drawn at this floor, labelled "0".
floor = 0.3
shown(e) = e < floor ? floor : e

do for [kind in "fill line"] {
    set output sprintf("%s/%s.svg", dir, kind)
    set title sprintf("%s: speed against accuracy", kind eq "fill" ? "Convex fills" : "Lines") font ",14"
    set xlabel sprintf("speed: million pixels per second drawing the %s of the 360-frame tumbling cube (higher is better)", \
        kind eq "fill" ? "front faces" : "culled edges")
    set ylabel "coverage mismatches per million pixels vs the exact reference (lower is better)"
    set logscale xy
    set ytics add ("0 (exact)" floor)
    set offsets graph 0.15, graph 0.35, graph 0.1, graph 0.1
    file = sprintf("%s/%s.csv", dir, kind)
    # Labels of exact methods would pile up on the floor: stack them upward, joined to their points.
    k = 0
    label_y(e) = e < floor ? (k = k + 1, floor * 2.2**k) : e
    plot sprintf("%s/%s-pareto.csv", dir, kind) using 4:(shown($5)) every ::1 with linespoints lw 2 lc "#999999" dt 2 pt 6 ps 3.2 title "Pareto front", \
         file using 4:(shown($5)) every ::1 with points pt 7 ps 1.3 lc "#3366cc" title "method", \
         file using 4:($3 == 1 ? shown($5) : 1/0) every ::1 with points pt 5 ps 2.2 lc "#d62728" title "product default", \
         (k = 0, file) using 4:(shown($5)):(0):(label_y($5) - shown($5)) every ::1 with vectors nohead lc "#bbbbbb" notitle, \
         (k = 0, file) using 4:(label_y($5)):($5 < floor ? stringcolumn(2) : "") every ::1 with labels offset char 1, char 0 left font ",10" notitle, \
         file using 4:(shown($5)):($5 < floor ? "" : stringcolumn(2)) every ::1 with labels offset char 0, char 1.2 center font ",10" notitle
    unset ytics
    set ytics
    unset logscale
}

set output sprintf("%s/speed.svg", dir)
set title "Speed by primitive size" font ",14"
set xlabel "triangle size or line length (px)"
set ylabel "million pixels per second"
set logscale xy
set key outside right
set offsets 0, 0, 0, 0
fills = "seed-bbox-float edge-float edge-fixed4 edge-fixed8 blocked-fixed8 scanline-float span-exact8"
lines = "seed-float-dda bresenham integer-dda"
plot for [m in fills] sprintf("%s/speed.csv", dir) using 2:(strcol(1) eq m && $2 > 0 ? $4 : 1/0) every ::1 \
        with linespoints lw (m eq "span-exact8" ? 3 : 1) title "fill ".m, \
     for [m in lines] sprintf("%s/speed.csv", dir) using 2:(strcol(1) eq m && $2 > 0 ? $4 : 1/0) every ::1 \
        with linespoints dt 2 lw (m eq "integer-dda" ? 3 : 1) title "line ".m
