#!/usr/bin/env bash
# Every include of the library runs from a stage to an earlier one, in the order written at the
# top of doc/architecture.md; `--self-test` proves the check fails on a backward include.
set -euo pipefail

# check ROOT: prints each include that runs against the order, exits 1 if there is one.
check() {
    local root=$1
    local order
    order=$(grep -m1 '^Stage order:' "$root/doc/architecture.md") || {
        echo "$root/doc/architecture.md has no 'Stage order:' line"
        return 1
    }
    local -A rank=()
    local i=0 stage
    for stage in $(grep -o '`[a-z]*/`' <<<"$order" | tr -d '`/'); do rank[$stage]=$((i++)); done
    [ "$i" -gt 1 ] || { echo "no stages in: $order"; return 1; }
    local status=0 file from to included
    while IFS= read -r -d '' file; do
        from=${file#"$root"/}
        from=${from#src/}
        from=${from#include/raster/}
        [[ $from == */* ]] || continue  # the umbrella header and generated files sit above every stage
        from=${from%%/*}
        if [[ ! -v rank[$from] ]]; then
            echo "${file#"$root"/}: folder '$from' is not in the stage order"
            status=1
            continue
        fi
        while IFS= read -r included; do
            to=${included#raster/}
            [[ $to == */* ]] || continue
            to=${to%%/*}
            [[ -v rank[$to] ]] || continue  # a third-party or standard header
            if ((rank[$to] > rank[$from])); then
                echo "${file#"$root"/}: $from/ includes $included, a later stage"
                status=1
            fi
        done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]\([^>"]*\)[>"].*/\1/p' "$file")
    done < <(find "$root/src" "$root/include/raster" -name '*.[ch]pp' -print0)
    return $status
}

if [ "${1:-}" = --self-test ]; then
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    mkdir -p "$scratch/doc" "$scratch/src/early" "$scratch/include/raster/late"
    echo 'Stage order: `early/` → `late/`' >"$scratch/doc/architecture.md"
    echo '#include <raster/early/a.hpp>' >"$scratch/include/raster/late/b.hpp"
    check "$scratch" >/dev/null || { echo "a forward include was refused"; exit 1; }
    echo '#include "late/b.hpp"' >"$scratch/src/early/a.cpp"
    if check "$scratch" >/dev/null; then
        echo "a backward include passed"
        exit 1
    fi
    echo "the check refuses a backward include and accepts a forward one"
    exit 0
fi
check "$1"
