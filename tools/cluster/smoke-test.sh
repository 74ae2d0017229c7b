#!/usr/bin/env bash
# smoke-test.sh [STATE_DIR] - start local Slurm, run a 4-task array + dependent job, check, stop.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
d=${1:-/tmp/slurm-proto}
t0=$(date +%s.%N)
trap '"$here/local-slurm.sh" stop "$d" || true' EXIT
env_line=$("$here/local-slurm.sh" start "$d")  # separate step: eval "$(...)" would hide a failure
eval "$env_line"
t1=$(date +%s.%N)
rm -f "$d"/out-* "$d/all.txt"
a=$(sbatch --parsable -o "$d/arr-%A_%a.log" --array=0-3 --wrap "echo \$SLURM_ARRAY_TASK_ID > $d/out-\$SLURM_ARRAY_TASK_ID")
# --wrap runs /bin/sh (dash on Debian): no brace expansion, so list files explicitly.
b=$(sbatch --parsable -o "$d/cat.log" --dependency=afterok:"$a" --wrap "cat $d/out-0 $d/out-1 $d/out-2 $d/out-3 > $d/all.txt")
state=
for _ in $(seq 120); do
  state=$(scontrol show job "$b" | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)
  case $state in COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY) break ;; esac
  sleep 0.5
done
t2=$(date +%s.%N)
[[ $state == COMPLETED ]] || { echo "smoke-test: dependent job $b ended '$state'" >&2; tail -n 5 "$d/cat.log" >&2 || true; exit 1; }
[[ $(tr '\n' ' ' <"$d/all.txt") == "0 1 2 3 " ]] || { echo "smoke-test: unexpected all.txt: $(cat "$d/all.txt")" >&2; exit 1; }
"$here/local-slurm.sh" stop "$d"; trap - EXIT
t3=$(date +%s.%N)
awk -v a="$t0" -v b="$t1" -v c="$t2" -v d="$t3" \
  'BEGIN { printf "smoke-test: OK start %.1fs, jobs %.1fs, stop %.1fs, total %.1fs\n", b-a, c-b, d-c, d-a }'
