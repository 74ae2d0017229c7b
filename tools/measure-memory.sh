#!/usr/bin/env bash
# Peak memory (maximum resident set, from GNU time) of `render` against canvas size, model size,
# frames and threads, and of an OBJ that is one enormous line. Prints a Markdown table.
# usage: tools/measure-memory.sh [BUILD_DIR]   (default build/release; needs /usr/bin/time)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
render="${1:-$root/build/release}/bin/render"
[ -x "$render" ] || { echo "measure-memory: build first (tools/bootstrap.sh test)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "measure-memory: needs GNU time (apt-get install time)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# A torus of N x M quads (2 N M triangles), written by awk so that no other tool is needed.
torus() {
    awk -v N="$1" -v M="$2" 'BEGIN {
        pi = atan2(0, -1)
        for (i = 0; i < N; i++) for (j = 0; j < M; j++) {
            u = 2 * pi * i / N; v = 2 * pi * j / M
            printf "v %.6f %.6f %.6f\n", (1 + 0.3 * cos(v)) * cos(u), 0.3 * sin(v), (1 + 0.3 * cos(v)) * sin(u)
        }
        for (i = 0; i < N; i++) for (j = 0; j < M; j++) {
            a = i * M + j + 1; b = ((i + 1) % N) * M + j + 1
            c = ((i + 1) % N) * M + (j + 1) % M + 1; d = i * M + (j + 1) % M + 1
            printf "f %d %d %d %d\n", a, b, c, d
        }
    }' > "$3"
}

# One row: what varies, the command's peak in MiB, its wall time, and its exit status.
measure() {
    local label="$1"
    shift
    local status=0
    /usr/bin/time -f "%M %e" -o "$work/time" "$render" "$@" -q >/dev/null 2>"$work/err" || status=$?
    read -r kib seconds < <(tail -n 1 "$work/time")  # a failed command adds a line before it
    printf '| %s | %d | %s | %s |\n' "$label" $(((kib + 512) / 1024)) "$seconds" "$([ "$status" -eq 0 ] && echo written || echo "refused: $(head -c 60 "$work/err")")"
}

torus 10 6 "$work/small.obj"        # 120 triangles
torus 70 36 "$work/t5k.obj"         # 5,040
torus 224 112 "$work/t50k.obj"      # 50,176
torus 708 354 "$work/t500k.obj"     # 501,264
cd "$work"
echo "| run | peak MiB | seconds | result |"
echo "|---|---:|---:|---|"
for side in 256 1024 4096 8192 16383; do
    measure "still, 120 triangles, ${side}x${side}" small.obj --width "$side" --height "$side" --effort fast out.webp
done
for model in t5k t50k t500k; do
    measure "still, $model.obj ($(grep -c '^f' "$model.obj") quads), 800x600" "$model.obj" --width 800 --height 600 out.webp
done
for frames in 1 16 64; do
    measure "turntable, 50,176 triangles, 1000x1000, $frames frames" t50k.obj --turntable "$frames" --width 1000 --height 1000 out.webp
done
for threads in 1 2 64; do
    measure "turntable, 50,176 triangles, 1000x1000, 16 frames, --threads $threads" t50k.obj --turntable 16 --width 1000 --height 1000 --threads "$threads" out.webp
done
# A 1000 MiB OBJ that is one line: refused at the 4 MiB line cap, having held at most that.
{ printf 'v 0 0 0\n# '; head -c $((1000 << 20)) /dev/zero | tr '\0' x; printf '\n'; } > one-line.obj
measure "one-line OBJ of 1000 MiB" one-line.obj out.webp
