#!/usr/bin/env bash
# raster against Mesa's software OpenGL (llvmpipe through OSMesa), every case on both sides,
# interleaved, REPETITIONS times (default 3): raster on 1 thread and on every core, llvmpipe with
# LP_NUM_THREADS=0 (one thread) and with its default. Writes doc/bench/gl-runs.csv (every run),
# doc/bench/gl.csv (medians and ratios), doc/bench/gl.md (the table) and doc/bench/gl-*.svg.
# Agreement (at one sample): unlit cases, the share of covered pixels equal on both sides; the lit
# scenes (ptah, point-lights, flythrough), the share within 2 levels on every channel. Also writes doc/images/bench-ptah-*.webp.
# Run by `tools/bootstrap.sh bench`, which builds build/release/bin/raster-vs-gl first.
set -euo pipefail
cd "$(dirname "$0")/.."
repetitions="${1:-3}"
bin=build/release/bin/raster-vs-gl
out=doc/bench
mkdir -p "$out"
# case width height frames samples; each sweep in consecutive rows, so that the charts join its
# points; then every case up to 1080p again at 4 samples per pixel (beyond it, 4 samples of an
# 8K frame take a gigabyte on each side).
cases=(
    "torus-16 800 600 45 1" "torus-8 800 600 120 1" "torus-4 800 600 360 1" "torus-2 800 600 720 1"
    "torus-1 800 600 1080 1" "torus-1 1280 720 540 1" "torus-1 1920 1080 270 1" "torus-1 3840 2160 60 1" "torus-1 7680 4320 15 1"
    "cube 800 600 1440 1" "ptah 800 600 120 1" "ptah 1920 1080 60 1" "point-lights 800 600 180 1" "flythrough 800 600 24 1"
    "torus-16 800 600 20 4" "torus-8 800 600 45 4" "torus-4 800 600 120 4" "torus-2 800 600 240 4"
    "torus-1 800 600 360 4" "torus-1 1280 720 180 4" "torus-1 1920 1080 90 4"
    "cube 800 600 480 4" "ptah 800 600 60 4" "ptah 1920 1080 24 4" "point-lights 800 600 90 4" "flythrough 800 600 24 4"
)
runs="$out/gl-runs.csv"
echo "repetition,side,case,width,height,facets,threads,frames,seconds,fps,agreement" > "$runs"
for ((r = 1; r <= repetitions; r++)); do
    for c in "${cases[@]}"; do
        read -r name width height frames samples <<<"$c"
        common=(--case "$name" --width "$width" --height "$height" --frames "$frames" --samples "$samples")
        agreement=()
        [ "$r" -eq 1 ] && [ "$width" -le 1920 ] && [ "$samples" -eq 1 ] && agreement=(--agreement)
        echo "$r,$("$bin" --side raster --threads 1 "${common[@]}" "${agreement[@]}")" >> "$runs"
        echo "$r,$("$bin" --side raster --threads 0 "${common[@]}")" >> "$runs"
        echo "$r,$(LP_NUM_THREADS=0 "$bin" --side gl "${common[@]}" | sed 's/^gl,/gl1,/')" >> "$runs"
        echo "$r,$(env -u LP_NUM_THREADS "$bin" --side gl "${common[@]}" | sed 's/^gl,/glN,/')" >> "$runs"
        echo "bench-gl: round $r, $name ${width}x$height, $samples sample(s)" >&2
    done
done
# Medians per case and side, then one row per case: fps of each, ratios, agreement. A ratio is
# the median of the rounds' own ratios, since both sides of a round ran side by side in time.
awk -F, 'NR > 1 {
    key = $3 "," $4 "," $5; side = $2 (($2 == "raster") ? $7 : "")
    n[key, side]++; v[key, side, n[key, side]] = $10; facets[key] = $6
    if ($11 >= 0) agree[key] = $11
    if (!(key in seen)) { seen[key] = 1; order[++keys] = key }
}
function middle(a, k,    i, j, t) {
    for (i = 1; i <= k; i++) for (j = i + 1; j <= k; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
    return (k % 2) ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2
}
function median(key, side,    k, i, a) {
    k = n[key, side]; for (i = 1; i <= k; i++) a[i] = v[key, side, i]
    return middle(a, k)
}
function ratio(key, top, bottom,    k, i, a) {
    k = n[key, top]; for (i = 1; i <= k; i++) a[i] = v[key, top, i] / v[key, bottom, i]
    m = middle(a, k); low = a[1]; high = a[k]  # middle() sorts
    return m
}
BEGIN { print "case,width,height,facets,raster1,rasterN,gl1,glN,ratio1,ratioN,agreement,ratio1_low,ratio1_high,ratioN_low,ratioN_high" }
END {
    for (o = 1; o <= keys; o++) {
        key = order[o]; r1 = median(key, "raster1"); rn = median(key, "raster0"); g1 = median(key, "gl1"); gn = median(key, "glN")
        q1 = ratio(key, "raster1", "gl1"); l1 = low; h1 = high; qn = ratio(key, "raster0", "glN"); ln = low; hn = high
        printf "%s,%s,%.1f,%.1f,%.1f,%.1f,%.2f,%.2f,%s,%.2f,%.2f,%.2f,%.2f\n", key, facets[key], r1, rn, g1, gn, q1, qn, (key in agree) ? agree[key] : "", l1, h1, ln, hn
    }
}' "$runs" > "$out/gl.csv"
{
    cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
    mesa=$(dpkg-query -W -f='${Version}' libosmesa6 2>/dev/null || echo unknown)
    echo "Machine: $cpu, $(nproc) cores; $(c++ --version | head -1); Mesa (libosmesa6) $mesa; $repetitions rounds, $(date -u +%Y-%m-%d)."
    echo
    echo "Frames per second are medians; a ratio is the median of the rounds' ratios, with their range."
    echo
    echo "| case | size | facets | raster, 1 thread | llvmpipe, 1 thread | ratio | raster, all cores | llvmpipe, default | ratio | pixels that agree |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
    awk -F, 'NR > 1 { printf "| %s | %sx%s | %s | %s | %s | %s (%s–%s) | %s | %s | %s (%s–%s) | %s |\n", $1, $2, $3, $4, $5, $7, $9, $12, $13, $6, $8, $10, $14, $15, ($11 == "") ? "" : sprintf("%.2f %%", 100 * $11) }' "$out/gl.csv"
    echo
    echo "What 4 samples per pixel cost: each side's time per frame at 4 samples over its time at 1 (medians, 1 thread each)."
    echo
    echo "| case | size | raster, 4x / 1x | llvmpipe, 4x / 1x |"
    echo "|---|---|---|---|"
    awk -F, 'NR > 1 { key = $1 "," $2 "," $3; r[key] = $5; g[key] = $7; order[NR] = key }
        END { for (i = 2; i <= NR; i++) { key = order[i]; split(key, k, ","); if (k[1] ~ / 4x$/) continue
            four = k[1] " 4x," k[2] "," k[3]; if (!(four in r)) continue
            printf "| %s | %sx%s | %.2f | %.2f |\n", k[1], k[2], k[3], r[key] / r[four], g[key] / g[four] } }' "$out/gl.csv"
} > "$out/gl.md"
"$bin" --side raster --case ptah --frames 1 --picture doc/images/bench-ptah >/dev/null
if command -v gnuplot >/dev/null; then gnuplot -e "dir='$out'" bench/gl_charts.gp; fi
echo "bench-gl: wrote $out/gl-runs.csv, $out/gl.csv, $out/gl.md" >&2
