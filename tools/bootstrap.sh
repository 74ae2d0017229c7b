#!/usr/bin/env bash
# Sets raster up on Debian 12 from nothing: installs missing packages, builds, then runs one job.
set -euo pipefail

usage() {
    cat <<'TXT'
usage: tools/bootstrap.sh COMMAND
  run [OUTPUT.webp]  build the exporters in Release and render the tumbling cube
                     (default out/animated-cube.webp, relative to where you are)
  format [--fix]     check that our C++ follows .clang-format (clang-format 14), showing what
                     would change; --fix rewrites the files instead (tools/check-format.sh)
  test               build in Release and run every test
  sanitize           build with AddressSanitizer and UndefinedBehaviorSanitizer and run every test
  fuzz [SECONDS]     build the libFuzzer targets with clang; fuzz fill and line, the mesh
                     pipeline, OBJ and texture loading and raster's PLY reader for SECONDS
                     each (default 60), then replay the glTF/STL/PLY target's seeds
  lab                measure every raster method and redraw the charts in doc/lab/
  cluster [DIR]      install Slurm and munge and start a one-node cluster on 127.0.0.1 with its
                     state in DIR (default /tmp/raster-slurm); prints the SLURM_CONF line to export,
                     and how to stop it (tools/cluster/local-slurm.sh stop DIR)
  bench [N]          build raster-vs-gl and time raster against Mesa's llvmpipe, every case
                     N times (default 3), interleaved; writes doc/bench/
  -h, --help         print this help
Each command first installs the Debian 12 packages it needs that are missing (apt-get, with
sudo when not root).
TXT
}

app_packages=(cmake g++ make pkg-config libglm-dev libwebp-dev libpng-dev libstb-dev libtinyobjloader-dev libassimp-dev nlohmann-json3-dev libcli11-dev)
base_packages=("${app_packages[@]}" libgtest-dev libbenchmark-dev webp assimp-testmodels ffmpeg)
# A one-node Slurm cluster for the Cluster test and the cluster job (tools/cluster/).
cluster_packages=(slurmctld slurmd slurm-client munge)

install_missing() {
    local missing=()
    for package in "$@"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
            missing+=("$package")
    done
    [ ${#missing[@]} -eq 0 ] && return
    local sudo=()
    [ "$(id -u)" -eq 0 ] || sudo=(sudo)
    echo "bootstrap: installing ${missing[*]}"
    "${sudo[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
    cmake --preset "$1"
    cmake --build --preset "$1" -j "$(nproc)"
}

caller_dir="$PWD"
cd "$(dirname "$0")/.."
case "${1:-}" in
run)
    output="${2:-out/animated-cube.webp}"
    [[ "$output" = /* || "$output" = - ]] || output="$caller_dir/$output"
    # The exporters alone, in their own tree: no tests, lab or Google Benchmark to build. Build
    # chatter goes to stderr, so that `run -` writes nothing but the image to stdout.
    {
        install_missing "${app_packages[@]}"
        cmake --preset apps
        cmake --build --preset apps -j "$(nproc)"
    } >&2
    [ "$output" = - ] || mkdir -p "$(dirname "$output")"
    build/apps/bin/animated-cube "$output"
    ;;
format)
    install_missing clang-format
    tools/check-format.sh ${2:+"$2"}
    ;;
test)
    install_missing "${base_packages[@]}" "${cluster_packages[@]}"
    build release
    ctest --preset release
    ;;
sanitize)
    install_missing "${base_packages[@]}"
    build asan
    ctest --preset asan
    ;;
fuzz)
    seconds="${2:-60}"
    install_missing "${base_packages[@]}" clang libclang-rt-14-dev
    build fuzz
    for target in fuzz_raster fuzz_mesh fuzz_model fuzz_ply fuzz_stl fuzz_scene; do
        mkdir -p "build/fuzz/corpus/$target"
        # New finds go to the first folder; the committed seeds (lab/seeds/) are read, never written.
        seeds=()
        [ -d "lab/seeds/$target" ] && seeds=("lab/seeds/$target")
        run=(-max_total_time="$seconds")
        # fuzz_scene reads through the child-process reader, where assimp's own faults (5.2.5 leaks,
        # and frees memory it never allocated) end as one line; it replays the committed hostile
        # files once each (lab/seeds/fuzz_scene); `fuzz_scene DIR` fuzzes it by hand.
        [ "$target" = fuzz_scene ] && run=(-runs=0 -timeout=10 -detect_leaks=0)
        build/fuzz/lab/$target "${run[@]}" -print_final_stats=1 "build/fuzz/corpus/$target" "${seeds[@]}"
    done
    ;;
lab)
    install_missing "${base_packages[@]}" gnuplot-nox libtinygltf-dev
    build release
    cmake --build --preset release --target lab
    ;;
cluster)
    state="${2:-/tmp/raster-slurm}"
    [[ "$state" = /* ]] || state="$caller_dir/$state"
    install_missing "${cluster_packages[@]}"
    tools/cluster/local-slurm.sh start "$state"
    echo "# stop it with: tools/cluster/local-slurm.sh stop $state" >&2
    ;;
bench)
    install_missing "${base_packages[@]}" gnuplot-nox libosmesa6-dev
    cmake --preset release -DRASTER_BUILD_BENCH=ON
    cmake --build --preset release -j "$(nproc)" --target raster-vs-gl
    tools/bench-gl.sh "${2:-3}"
    ;;
-h | --help)
    usage
    ;;
*)
    usage >&2
    exit 2
    ;;
esac
