#!/usr/bin/env bash
# Sets raster up on Debian 12 from nothing: installs missing packages, builds in Release, then
# runs the main job (`run`) or the whole test suite (`test`).
set -euo pipefail

usage() {
    echo "usage: tools/bootstrap.sh run [OUTPUT.webp]   # render the tumbling cube (default out/animated-cube.webp)"
    echo "       tools/bootstrap.sh test                # run every test"
}

packages=(cmake g++ make pkg-config libglm-dev libwebp-dev libcli11-dev libgtest-dev webp)

install_missing() {
    local missing=()
    for package in "${packages[@]}"; do
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
    cmake --preset release
    cmake --build --preset release -j "$(nproc)"
}

cd "$(dirname "$0")/.."
case "${1:-}" in
run)
    output="${2:-out/animated-cube.webp}"
    install_missing
    build
    mkdir -p "$(dirname "$output")"
    build/release/bin/animated-cube "$output"
    ;;
test)
    install_missing
    build
    ctest --preset release
    ;;
*)
    usage >&2
    exit 2
    ;;
esac
