#!/usr/bin/env bash
# Renders one clip on a Slurm cluster: a job array of frame ranges, then a dependent assemble job.
set -euo pipefail

usage() {
    cat <<'TXT'
usage: tools/cluster/submit-clip.sh TASKS FRAMES OUT.webp PARTS_DIR PROGRAM [ARGS...]
  Submits a job array of TASKS tasks, each rendering its share of the FRAMES frames with
  PROGRAM ARGS --frame-range A..B --skip-existing PARTS_DIR/part-NNNN.webp, and a job that runs
  webp-assemble OUT.webp on the parts once every task has succeeded. PROGRAM is an exporter
  (animated-scene, animated-cube, render ... --turntable FRAMES) that every node can run from
  the same path; PARTS_DIR and OUT.webp must be on storage every node shares.
  Prints the two job ids. Extra sbatch options go in SBATCH_OPTIONS (e.g. "-p batch").
example:
  tools/cluster/submit-clip.sh 8 360 scene.webp parts build/release/bin/animated-scene --scene islands --frames 360
TXT
}
[ "${1:-}" = -h ] || [ "${1:-}" = --help ] && { usage; exit 0; }
[ $# -ge 5 ] || { echo "submit-clip: expected TASKS FRAMES OUT.webp PARTS_DIR PROGRAM (see --help)" >&2; exit 2; }
tasks=$1 frames=$2 out=$3 parts=$4
shift 4
[[ $tasks =~ ^[1-9][0-9]*$ && $frames =~ ^[1-9][0-9]*$ ]] || { echo "submit-clip: TASKS and FRAMES are positive whole numbers" >&2; exit 2; }
[ "$tasks" -le "$frames" ] || { echo "submit-clip: $tasks tasks for $frames frames would leave a task nothing to render" >&2; exit 2; }
command -v sbatch >/dev/null || { echo "submit-clip: sbatch not found: is this a Slurm submit host?" >&2; exit 1; }
program=$(command -v "$1") || { echo "submit-clip: '$1' is not a program" >&2; exit 1; }
shift
assemble="$(dirname "$program")/webp-assemble"
[ -x "$assemble" ] || { echo "submit-clip: no webp-assemble beside $program" >&2; exit 1; }
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$parts"
parts=$(cd "$parts" && pwd)
read -r -a extra <<<"${SBATCH_OPTIONS:-}"
array=$(sbatch --parsable "${extra[@]}" --array=0-$((tasks - 1)) -o "$parts/task-%a.log" \
    "$here/render-clip.sbatch" "$tasks" "$frames" "$parts" "$program" "$@")
names=()
for ((k = 0; k < tasks; ++k)); do names+=("$(printf '%s/part-%04d.webp' "$parts" "$k")"); done
# --wrap runs /bin/sh, so the part names are listed, quoted, rather than globbed.
# shellcheck source=sh-quote.sh
source "$here/sh-quote.sh"
assembly=$(sbatch --parsable "${extra[@]}" --dependency=afterok:"${array%%;*}" -o "$parts/assemble.log" --job-name=raster-assemble \
    --wrap "$(sh_quote "$assemble" --quiet "$out" "${names[@]}")")
echo "$array $assembly"
