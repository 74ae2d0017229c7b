#!/usr/bin/env bash
# Renders one clip with GNU parallel over ssh (or locally): one frame range per job, then assembles.
set -euo pipefail

usage() {
    cat <<'TXT'
usage: tools/cluster/parallel-clip.sh TASKS FRAMES OUT.webp PARTS_DIR PROGRAM [ARGS...]
  Runs TASKS jobs with GNU parallel, each rendering its share of the FRAMES frames with
  PROGRAM ARGS --frame-range A..B --skip-existing PARTS_DIR/part-NNNN.webp, then joins the parts
  with webp-assemble. With RASTER_SSH_LOGINS=FILE (parallel's --sshloginfile: one "N/host"
  per line, ":" for this machine) the jobs run on those machines, which must share PARTS_DIR
  and PROGRAM's path (e.g. over NFS); without it they run here. Run it again after a failure:
  parts already complete are kept.
TXT
}
[ "${1:-}" = -h ] || [ "${1:-}" = --help ] && { usage; exit 0; }
[ $# -ge 5 ] || { echo "parallel-clip: expected TASKS FRAMES OUT.webp PARTS_DIR PROGRAM (see --help)" >&2; exit 2; }
tasks=$1 frames=$2 out=$3 parts=$4
shift 4
[[ $tasks =~ ^[1-9][0-9]*$ && $frames =~ ^[1-9][0-9]*$ ]] || { echo "parallel-clip: TASKS and FRAMES are positive whole numbers" >&2; exit 2; }
[ "$tasks" -le "$frames" ] || { echo "parallel-clip: $tasks tasks for $frames frames would leave a task nothing to render" >&2; exit 2; }
command -v parallel >/dev/null || { echo "parallel-clip: GNU parallel is not installed (apt-get install parallel)" >&2; exit 1; }
program=$(command -v "$1") && program=$(realpath "$program") || { echo "parallel-clip: '$1' is not a program" >&2; exit 1; }
shift
[ -x "$(dirname "$program")/webp-assemble" ] || { echo "parallel-clip: no webp-assemble beside $program" >&2; exit 1; }
mkdir -p "$parts"
parts=$(cd "$parts" && pwd)
where=()
[ -n "${RASTER_SSH_LOGINS:-}" ] && where=(--sshloginfile "$RASTER_SSH_LOGINS")
# Task k of n takes frames k*F/n to (k+1)*F/n - 1, as render-clip.sbatch does.
# --workdir: remote jobs start where this one runs (the shared storage), not in $HOME.
seq 0 $((tasks - 1)) | parallel --halt now,fail=1 --workdir "$PWD" "${where[@]}" \
    "$(printf '%q ' "$program" "$@") --quiet --skip-existing --frame-range \$(({}*$frames/$tasks))..\$((({}+1)*$frames/$tasks-1)) $(printf '%q' "$parts")/part-\$(printf %04d {}).webp"
names=()
for ((k = 0; k < tasks; ++k)); do names+=("$(printf '%s/part-%04d.webp' "$parts" "$k")"); done
"$(dirname "$program")/webp-assemble" "$out" "${names[@]}"
