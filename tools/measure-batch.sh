#!/usr/bin/env bash
# Throughput of `render` on 100 small models, three ways: one batch process (--output-dir), one
# process per model in a shell loop, and one process per model two at a time (xargs -P 2). The
# methods are interleaved REPETITIONS times (default 7); each is reported as its median wall time
# with min-max and as models per second (100 / median). Prints a Markdown table.
# usage: [RENDER=path/to/render] [EFFORT=fast|default|max] tools/measure-batch.sh [REPETITIONS]
#   RENDER defaults to build/release/bin/render, EFFORT (render's --effort) to default; the
#   models are copies of Debian's assimp-testmodels (/usr/share/assimp/models, or
#   ASSIMP_MODELS), 20 each of five files.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
repetitions="${1:-7}"
render="${RENDER:-$root/build/release/bin/render}"
case "$render" in
    /*) ;;
    */*) render="$PWD/$render" ;;
    *) render="$(command -v "$render" || true)" ;;
esac
[ -x "$render" ] || { echo "measure-batch: no render at '${RENDER:-$root/build/release/bin/render}' (build first: tools/bootstrap.sh test)" >&2; exit 1; }
[[ "$repetitions" =~ ^[1-9][0-9]*$ ]] || { echo "measure-batch: REPETITIONS must be a positive whole number" >&2; exit 1; }
models="${ASSIMP_MODELS:-/usr/share/assimp/models}"
[ -d "$models" ] || { echo "measure-batch: needs $models (apt-get install assimp-testmodels)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
effort="${EFFORT:-default}"
size=(--width 256 --height 256 --effort "$effort")

# The corpus: per kind, the name stem, the source file and what it is. The spider OBJ names
# spider.mtl, whose five JPEG textures are copied beside it once.
kinds=(
    "box OBJ/box.obj OBJ, 12 triangles, no material library"
    "spider OBJ/spider.obj OBJ with MTL and 5 JPEG textures, 1312 triangles"
    "spiderstl STL/Spider_binary.stl binary STL, 1312 triangles"
    "cube PLY/cube.ply ASCII PLY, 12 triangles"
    "boxtex glTF2/BoxTextured-glTF-Binary/BoxTextured.glb GLB with an embedded PNG texture, 12 triangles"
)
per_kind=20
corpus="$work/models"
mkdir -p "$corpus"
cp "$models/OBJ/spider.mtl" "$models"/OBJ/{wal67ar_small,wal69ar_small,SpiderTex,drkwood2,engineflare1}.jpg "$corpus/"
files=()
mix=()
for k in "${kinds[@]}"; do
    read -r stem source what <<<"$k"
    ext="${source##*.}"
    # Each file must render alone before it is copied 20 times; what it prints goes to stderr.
    base="$(basename "$source")"
    cp "$models/$source" "$corpus/$base"
    (cd "$corpus" && "$render" "$base" "$work/check.webp" "${size[@]}") >/dev/null 2>"$work/err" \
        || { echo "measure-batch: $source does not render alone:" >&2; cat "$work/err" >&2; exit 1; }
    [ -s "$work/err" ] && sed "s|^|measure-batch: $source alone: |" "$work/err" >&2
    rm -f "$corpus/$base" "$work/check.webp"
    for ((i = 1; i <= per_kind; i++)); do
        name="$(printf '%s-%02d.%s' "$stem" "$i" "$ext")"
        cp "$models/$source" "$corpus/$name"
        files+=("$name")
    done
    mix+=("$per_kind × \`$(basename "$source")\` ($what)")
done
count=${#files[@]}

out="$work/out"
# Every run must leave one non-empty picture per model, and print nothing (-q).
check() {
    local method="$1" written
    written="$(find "$out" -name '*.webp' -size +0 | wc -l)"
    if [ "$written" -ne "$count" ] || [ -s "$work/err" ]; then
        echo "measure-batch: $method wrote $written of $count pictures" >&2
        cat "$work/err" >&2
        exit 1
    fi
}
run() {  # method: runs it once into an empty $out, prints its wall time in seconds
    local method="$1" start end status=0
    rm -rf "$out"
    mkdir -p "$out"
    cd "$corpus"
    start="$(date +%s.%N)"
    case "$method" in
        batch) "$render" "${files[@]}" --output-dir "$out" "${size[@]}" -q 2>"$work/err" || status=$? ;;
        loop) for f in "${files[@]}"; do "$render" "$f" "$out/${f%.*}.webp" "${size[@]}" -q || status=$?; done 2>"$work/err" ;;
        xargs) for f in "${files[@]}"; do printf '%s\0%s\0' "$f" "$out/${f%.*}.webp"; done \
            | xargs -0 -n 2 -P 2 "$render" "${size[@]}" -q 2>"$work/err" || status=$? ;;
    esac
    end="$(date +%s.%N)"
    cd "$root"
    [ "$status" -eq 0 ] || { echo "measure-batch: $method exited with status $status" >&2; cat "$work/err" >&2; exit 1; }
    check "$method"
    awk -v start="$start" -v end="$end" 'BEGIN { printf "%.3f\n", end - start }'
}

methods=(batch loop xargs)
declare -A times
same=yes
for ((r = 1; r <= repetitions; r++)); do
    for m in "${methods[@]}"; do
        t="$(run "$m")"
        times[$m]+="$t "
        # The first round also checks that every method wrote the same bytes.
        if [ "$r" -eq 1 ]; then
            if [ "$m" = batch ]; then rm -rf "$work/first"; cp -r "$out" "$work/first"
            elif ! diff -r -q "$work/first" "$out" >/dev/null; then same=no; echo "measure-batch: $m's pictures differ from the batch's" >&2
            fi
        fi
        printf 'measure-batch: round %d of %d, %s: %.2f s\n' "$r" "$repetitions" "$m" "$t" >&2
    done
done

label() {
    case "$1" in
        batch) echo "one process: \`render <$count files> --output-dir OUT\`" ;;
        loop) echo "one process per model, one after another (shell loop)" ;;
        xargs) echo "one process per model, two at a time (\`xargs -P 2\`)" ;;
    esac
}
cpu="$(grep -m 1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
joined="$(printf '%s; ' "${mix[@]}")"
echo "Corpus: $count models, ${joined%; }, rendered at 256 × 256 with \`--effort $effort -q\`."
echo "Machine: $cpu, $(nproc) cores, Debian $(cat /etc/debian_version); $("$render" --version); $repetitions interleaved rounds, $(date +%Y-%m-%d)."
echo "Every run wrote $count pictures; the three methods' pictures were byte for byte the same: $same."
echo
echo "| method | median s | min–max s | models/s |"
echo "|---|---:|---:|---:|"
for m in "${methods[@]}"; do
    # shellcheck disable=SC2086
    printf '%s\n' ${times[$m]} | sort -g | awk -v label="$(label "$m")" -v n="$count" '
        { v[NR] = $1 }
        END {
            median = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
            printf "| %s | %.2f | %.2f–%.2f | %.0f |\n", label, median, v[1], v[NR], n / median
        }'
done
