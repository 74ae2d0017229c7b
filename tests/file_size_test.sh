#!/usr/bin/env bash
# No C++ file of ours is over 400 lines, and one over 250 says in its first line why it stays
# whole (doc/architecture.md#the-map); `--self-test` proves the check can fail.
set -euo pipefail

check() {
    local root=$1 status=0 file lines
    while IFS= read -r -d '' file; do
        lines=$(wc -l <"$file")
        if [ "$lines" -gt 400 ]; then
            echo "${file#"$root"/}: $lines lines, over 400: split it along its concepts"
            status=1
        elif [ "$lines" -gt 250 ] && ! head -1 "$file" | grep -qi '^//.*stays whole'; then
            echo "${file#"$root"/}: $lines lines and no first-line comment saying why it stays whole"
            status=1
        fi
    done < <(find "$root/src" "$root/include" "$root/apps" "$root/lab" "$root/bench" "$root/tests" \
        -name '*.[ch]pp' -print0 2>/dev/null)
    return $status
}

if [ "${1:-}" = --self-test ]; then
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    mkdir -p "$scratch/src"
    { echo '// One table; stays whole so the rows read together.'; seq 300 | sed 's#^#// #'; } >"$scratch/src/a.cpp"
    check "$scratch" >/dev/null || { echo "a long file with its reason was refused"; exit 1; }
    seq 300 | sed 's#^#// #' >"$scratch/src/b.cpp"
    if check "$scratch" >/dev/null; then echo "a long file without a reason passed"; exit 1; fi
    rm "$scratch/src/b.cpp"
    { echo '// stays whole'; seq 401 | sed 's#^#// #'; } >"$scratch/src/c.cpp"
    if check "$scratch" >/dev/null; then echo "a file over 400 lines passed"; exit 1; fi
    echo "the check refuses long files without a reason and files over 400 lines"
    exit 0
fi
check "$1"
