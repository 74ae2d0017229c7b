#!/usr/bin/env bash
# Big models, measured: writes the 1 M, 2 M and 10 M-triangle models of issue 31 (a height-field
# grid as OBJ, a wavy sphere as binary PLY and STL) and a 10 M-point cloud, renders each with
# --timings, and prints a Markdown table of wall time, peak memory and each stage's time; with
# --baseline, another render binary alternates with this one (doc/performance.md#big-models-bench).
set -euo pipefail

usage() {
    cat <<'TXT'
usage: tools/bench-big-models.sh [--sizes "1 2 10"] [--rounds N] [--threads N] [--baseline RENDER] [--dir DIR]
  --sizes     millions of triangles for each model (default "1 2 10"); the cloud is 10 M points
              whenever 10 is among them
  --rounds    renders of each model by each binary, alternated (default 3)
  --threads   render's --threads (default: every core)
  --baseline  a render binary of an earlier release (built from its tag) to alternate with
  --dir       where the models are written, and kept for the next run (default /tmp/raster-big-models)
  Needs build/release (tools/bootstrap.sh run) and GNU time (/usr/bin/time); f3d, where installed,
  renders each model once for comparison. Models take about 1.5 GB at the default sizes.
TXT
}

sizes="1 2 10" rounds=3 threads=$(nproc) baseline="" dir=/tmp/raster-big-models
while [ $# -gt 0 ]; do
    case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --baseline) baseline="$2"; shift 2 ;;
    --dir) dir="$2"; shift 2 ;;
    -h | --help) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
    esac
done
root="$(cd "$(dirname "$0")/.." && pwd)"
render="$root/build/release/bin/render" generate="$root/build/release/bin/model-gen"
for tool in "$render" "$generate" /usr/bin/time; do
    [ -x "$tool" ] || { echo "bench-big-models: $tool is missing (tools/bootstrap.sh run builds ours; apt install time)" >&2; exit 1; }
done
[ -z "$baseline" ] || [ -x "$baseline" ] || { echo "bench-big-models: no render binary at $baseline" >&2; exit 1; }
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "bench-big-models: --rounds must be a whole number above 0" >&2; exit 2; }
mkdir -p "$dir"

models=()
for size in $sizes; do
    [[ "$size" =~ ^[1-9][0-9]?$ ]] || { echo "bench-big-models: sizes are millions from 1 to 99, got '$size'" >&2; exit 2; }
    for model in "grid obj" "sphere ply" "sphere stl"; do
        set -- $model
        file="$dir/$1-${size}m.$2"
        [ -f "$file" ] || "$generate" "$1" "${size}000000" "$file" >&2
        models+=("$file")
    done
    if [ "$size" = 10 ]; then
        file="$dir/cloud-10m.ply"
        [ -f "$file" ] || "$generate" cloud 10000000 "$file" >&2
        models+=("$file")
    fi
done

out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
# One render: "wall_s peak_MiB read prepare draw encode" (stage wall seconds, from --timings,
# which a baseline before 0.1.40 lacks: it is asked of this build only).
measure() {  # binary model [--timings]
    local log="$out/log" picture="$out/picture.webp"
    rm -f "$picture"
    if ! /usr/bin/time -f "%e %M" -o "$out/time" "$1" "$2" "$picture" --threads "$threads" ${3:-} -q 2>"$log"; then
        echo "bench-big-models: $1 failed on $2: $(tail -1 "$log")" >&2
        echo "- - - - - -"
        return
    fi
    read -r wall kb <"$out/time"
    stage() { awk -v name="$1" '$1 == name { print $2 }' "$log"; }
    echo "$wall $((kb / 1024)) $(stage read) $(stage prepare) $(stage draw) $(stage encode)"
}

range() { sort -n | awk 'NR == 1 { low = $1 } { high = $1 } END { printf(low == high ? "%s" : "%s–%s", low, high) }'; }
column() { awk -v k="$2" '{ print $k }' "$out/$1"; }  # column FILE K: field K of each measurement
median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "render --threads $threads, $rounds rounds, $(date -u +%Y-%m-%d), $(nproc) cores"
echo
if [ -n "$baseline" ]; then
    echo "| model | file | baseline wall, s | now | baseline peak, MiB | now | read | prepare | draw | encode |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
else
    echo "| model | file | wall, s | peak, MiB | read | prepare | draw | encode |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|"
fi
for model in "${models[@]}"; do
    : >"$out/now" && : >"$out/base"
    for ((r = 0; r < rounds; ++r)); do  # alternated, so drift in the machine touches both alike
        [ -z "$baseline" ] || measure "$baseline" "$model" >>"$out/base"
        measure "$render" "$model" --timings >>"$out/now"
    done
    megabytes=$(($(stat -c %s "$model") / 1000000))
    stages="$(column now 3 | median) | $(column now 4 | median) | $(column now 5 | median) | $(column now 6 | median)"
    if [ -n "$baseline" ]; then
        echo "| $(basename "$model") | $megabytes MB | $(column base 1 | range) | $(column now 1 | range) | $(column base 2 | median) | $(column now 2 | median) | $stages |"
    else
        echo "| $(basename "$model") | $megabytes MB | $(column now 1 | range) | $(column now 2 | median) | $stages |"
    fi
done
echo
echo "Stages: medians of render --timings' wall seconds for this build."
if command -v f3d >/dev/null; then
    echo
    echo "| model | f3d wall, s |"
    echo "|---|---:|"
    for model in "${models[@]}"; do
        /usr/bin/time -f "%e" -o "$out/time" f3d --output "$out/f3d.png" --resolution 800,600 "$model" >/dev/null 2>&1 &&
            echo "| $(basename "$model") | $(cat "$out/time") |" || echo "| $(basename "$model") | failed |"
    done
fi
