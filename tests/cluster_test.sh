#!/usr/bin/env bash
# A four-task Slurm job array and its assembly on a one-node cluster on loopback give exactly
# the frames of one run. Exits 77 (skipped) when Slurm and munge are not installed.
set -euo pipefail
source_dir=$1 bin_dir=$2
for daemon in munged slurmctld slurmd sbatch; do
    command -v "$daemon" >/dev/null || { echo "Slurm or munge is not installed (apt-get install slurmctld slurmd slurm-client munge): skipped"; exit 77; }
done
work=$(mktemp -d "${TMPDIR:-/tmp}/raster-cluster.XXXXXX")
chmod 755 "$work"  # munged wants every directory above its socket searchable by all
cluster="$source_dir/tools/cluster"
trap '"$cluster/local-slurm.sh" stop "$work/slurm" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
cd "$work"
env_line=$("$cluster/local-slurm.sh" start "$work/slurm")
eval "$env_line"

clip=("$bin_dir/animated-scene" --scene islands --frames 12 --width 96 --height 72 --effort fast)
"${clip[@]}" --quiet whole.webp
read -r array assembly < <("$cluster/submit-clip.sh" 4 12 joined.webp parts "${clip[@]}")
state=
deadline=$((SECONDS + 150))  # one limit for every wait, well inside CTest's 300 s
while [ "$SECONDS" -lt "$deadline" ]; do
    state=$(scontrol show job "$assembly" | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)
    case $state in COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY) break ;; esac
    sleep 0.5
done
if [ "$state" != COMPLETED ]; then
    echo "FAIL: the assembly job ended '$state' (array $array)"
    tail -n 3 parts/*.log
    exit 1
fi
ls parts/part-000{0,1,2,3}.webp >/dev/null
"$bin_dir/webp-frames" --quiet whole.webp one-run
"$bin_dir/webp-frames" --quiet joined.webp cluster
count=$(find one-run -name '*.png' | wc -l)
[ "$count" -eq 12 ] || { echo "FAIL: one run gave $count frames, not 12"; exit 1; }
count=$(find cluster -name '*.png' | wc -l)
[ "$count" -eq 12 ] || { echo "FAIL: the cluster's clip has $count frames, not 12"; exit 1; }
for frame in one-run/*.png; do
    cmp -s "$frame" "cluster/$(basename "$frame")" || { echo "FAIL: $(basename "$frame") differs from one run's"; exit 1; }
done

# A collection: each of two tasks draws its chunk of the list, as one process draws them all.
for k in 1 2 3; do
    printf 'v 0 0 0\nv 1 0 0\nv 0 %s 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n' "$k" >"model$k.obj"
done
printf '%s\n' "$work/model1.obj" "$work/model2.obj" "$work/model3.obj" >models.txt
"$bin_dir/render" --quiet --width 64 --height 48 --output-dir one-process model1.obj model2.obj model3.obj
collection=$(sbatch --parsable --array=0-1 -o "$work/collection-%a.log" "$cluster/render-collection.sbatch" models.txt "$work/thumbs" \
    "$bin_dir/render" --quiet --width 64 --height 48)
while [ "$SECONDS" -lt "$deadline" ]; do
    [ -z "$(squeue -h -j "$collection" 2>/dev/null)" ] && break
    sleep 0.5
done
for k in 1 2 3; do
    cmp -s "one-process/model$k.webp" "thumbs/model$k.webp" || { echo "FAIL: thumbs/model$k.webp differs from one process's"; tail -n 3 collection-*.log; exit 1; }
done
echo "Cluster: 4 Slurm tasks and their assembly gave the 12 frames of one run exactly; 2 tasks drew a collection of 3 models as one process does"
