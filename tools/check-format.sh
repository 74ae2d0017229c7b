#!/usr/bin/env bash
# Checks that the project's own C++ files follow .clang-format; --fix rewrites them in place.
set -euo pipefail

usage() {
    cat <<'TXT'
usage: tools/check-format.sh [--fix]
  (no option)  list every C++ file under src include apps lab bench tests that clang-format
               would change, with the changes, and fail if there is one
  --fix        rewrite those files in place instead
  -h, --help   print this help
CLANG_FORMAT names the clang-format to run (default clang-format; the style is written for 14).
TXT
}

mode=check
case "${1:-}" in
"") ;;
--fix) mode=fix ;;
-h | --help)
    usage
    exit 0
    ;;
*)
    usage >&2
    exit 2
    ;;
esac

cd "$(dirname "$0")/.."
clang_format="${CLANG_FORMAT:-clang-format}"
command -v "$clang_format" >/dev/null || {
    echo "check-format: $clang_format not found (tools/bootstrap.sh format installs it)" >&2
    exit 2
}
folders=(src include apps lab bench tests)
# Tracked and new files alike, never what lies under build/ or is ignored; find outside a clone.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -d '' files < <(git ls-files -z --cached --others --exclude-standard -- \
        "${folders[@]/%//*.cpp}" "${folders[@]/%//*.hpp}")
else
    mapfile -d '' files < <(find "${folders[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' \) -print0 | sort -z)
fi
[ ${#files[@]} -gt 0 ] || {
    echo "check-format: no C++ files found" >&2
    exit 2
}

if [ "$mode" = fix ]; then
    printf '%s\0' "${files[@]}" | xargs -0 -n 32 "$clang_format" -i --style=file
    echo "check-format: formatted ${#files[@]} files"
    exit 0
fi
unformatted=0
for file in "${files[@]}"; do
    "$clang_format" --dry-run -Werror --style=file "$file" 2>/dev/null && continue
    unformatted=$((unformatted + 1))
    "$clang_format" --style=file "$file" | diff -u --label "$file" --label "$file (formatted)" "$file" - || true
done
if [ "$unformatted" -gt 0 ]; then
    echo "check-format: $unformatted of ${#files[@]} files need formatting: tools/check-format.sh --fix" >&2
    exit 1
fi
echo "check-format: ${#files[@]} files formatted"
