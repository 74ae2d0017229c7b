#!/usr/bin/env bash
# bench/model_gen.cpp, which tools/bench-big-models.sh measures with: each shape in each format it
# writes is a model render reads with the size asked, and every mistake is one line and exit 1,
# with nothing written over a file that is there.
# Usage: model_gen_test.sh MODEL_GEN RENDER
set -euo pipefail
generate="$1" render="$2"
work="$(mktemp -d)"
trap 'rm -rf -- "$work"' EXIT
status=0
check() {  # check DESCRIPTION EXPECTED ACTUAL
    if [ "$2" != "$3" ]; then
        echo "FAIL: $1: expected '$2', got '$3'"
        status=1
    fi
}
contents() {  # contents MODEL: what render's report says it drew
    "$render" "$1" "$work/picture.webp" --width 16 --height 12 --threads 1 | sed -E 's/.*bytes, (.*), [0-9.]+ s$/\1/'
    rm -f "$work/picture.webp"
}
"$generate" grid 784 "$work/grid.obj" >/dev/null  # 28 x 14 cells: the count asked, exactly
check "grid as OBJ" "784 triangles" "$(contents "$work/grid.obj")"
"$generate" sphere 800 "$work/sphere.ply" >/dev/null
"$generate" sphere 800 "$work/sphere.stl" >/dev/null
# The poles' triangles have no area and are not drawn: the PLY and STL agree on the rest.
check "sphere as PLY and STL" "$(contents "$work/sphere.ply")" "$(contents "$work/sphere.stl")"
drawn="$(contents "$work/sphere.ply" | cut -d' ' -f1)"
check "sphere's triangles, but for one pole's fan (28)" 756 "$drawn"
"$generate" cloud 500 "$work/cloud.ply" >/dev/null
check "cloud as PLY" "500 points" "$(contents "$work/cloud.ply")"
"$generate" cloud 500 "$work/cloud.obj" >/dev/null
check "cloud as OBJ" "500 points" "$(contents "$work/cloud.obj")"

refused() {  # refused EXPECTED_MESSAGE ARGS...: exit 1 and that one line
    local expected="$1" code=0 said
    shift
    said="$("$generate" "$@" 2>&1 >/dev/null)" || code=$?
    check "exit of model-gen $*" 1 "$code"
    check "message of model-gen $*" "$expected" "$said"
}
before="$(md5sum <"$work/grid.obj")"
refused "model-gen: $work/grid.obj exists; remove it first" grid 784 "$work/grid.obj"
check "an existing file is left alone" "$before" "$(md5sum <"$work/grid.obj")"
refused "model-gen: an STL holds triangles, not a point cloud" cloud 10 "$work/cloud.stl"
refused "model-gen: no shape 'cube': grid, sphere or cloud" cube 10 "$work/cube.obj"
refused "model-gen: COUNT must be a whole number from 2 to 100000000, got '1e3'" grid 1e3 "$work/big.obj"
refused "model-gen: FILE must end in .obj, .ply or .stl" grid 10 "$work/grid.gltf"
code=0
"$generate" grid >/dev/null 2>&1 || code=$?
check "exit of model-gen with one word (usage)" 2 "$code"
check "exit of model-gen --help" 0 "$("$generate" --help >/dev/null && echo 0)"
check "nothing left half written" "cloud.obj cloud.ply grid.obj sphere.ply sphere.stl" "$(cd "$work" && echo *)"
exit $status
