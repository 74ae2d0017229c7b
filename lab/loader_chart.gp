# Draws loaders.svg from loader-lab's CSV:  gnuplot -e "dir='doc/lab'" lab/loader_chart.gp
if (!exists("dir")) dir = "doc/lab"
set datafile separator ","
file = sprintf("%s/loaders.csv", dir)
# One row per well-formed file (the malformed ones have no times), first file at the top.
stats file using (strcol(1) eq "wellformed" ? $2 : 1/0) every ::1 nooutput
rows = STATS_max
set terminal svg size 1000,720 dynamic enhanced font "sans,12" background "white"
set output sprintf("%s/loaders.svg", dir)
set title "Loading assimp-testmodels: median per load, bar from fastest to slowest round" font ",13"
set xlabel "milliseconds per load (log scale, lower is better)"
set logscale x
set format x "%g"
set xrange [0.005:2000]  # room on the right for the key
set yrange [rows + 0.6:-0.6]
set ytics scale 0 font ",11" nomirror noenhanced
set grid xtics mxtics lw 0.5 lc "#dddddd"
set key inside top right box opaque spacing 1.1 samplen 2
# Each loader's points sit a little above or below the file's line so that none hides another.
row(name, offset) = (strcol(1) eq "wellformed" && strcol(5) eq name) ? $2 + offset : 1/0
# Each file's name, with the triangles the loaders draw (those with area): written by every row of
# the file alike, since a later label at the same place replaces an earlier one (gnuplot's
# functions need an argument, hence the unused one).
label(dummy) = (strcol(1) eq "wellformed" && valid(14)) ? sprintf("%s  (%d triangle%s)", strcol(3), $14 - $15, $14 - $15 == 1 ? "" : "s") : strcol(3)
plot file using (1/0):2:ytic(label(0)) every ::1 with points notitle, \
     file using 9:(row("product", -0.24)):12:13 every ::1 with xerrorbars pt 7 ps 0.9 lc "#d62728" title "product (read\\_model)", \
     file using 9:(row("product-nomaps", -0.12)):12:13 every ::1 with xerrorbars pt 6 ps 0.9 lc "#ff7f0e" title "product, maps not decoded", \
     file using 9:(row("assimp", 0)):12:13 every ::1 with xerrorbars pt 5 ps 0.8 lc "#1f77b4" title "assimp ReadFile alone", \
     file using 9:(row("tinygltf", 0.12)):12:13 every ::1 with xerrorbars pt 9 ps 1.0 lc "#2ca02c" title "tinygltf", \
     file using 9:(row("tinyobjloader", 0.24)):12:13 every ::1 with xerrorbars pt 11 ps 1.0 lc "#9467bd" title "tinyobjloader"
