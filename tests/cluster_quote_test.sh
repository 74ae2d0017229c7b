#!/usr/bin/env bash
# submit-clip.sh's sh_quote: names with spaces, quotes, $, backquotes, newlines and non-ASCII
# come through /bin/sh (what sbatch --wrap runs) as they were given.
set -euo pipefail
source_dir=$1
source "$source_dir/tools/cluster/sh-quote.sh"
given=("plain" "with space" "it's" "'" "''" 'dollar $HOME `id` $(id) ${x:-y}' 'back\slash\' '"double"' "tab	here"
    $'new\nline' "ünïcødé ✓ 图" "" "-n" "*" "glob?[a]" "semi;colon&amp|pipe>out" "~")
line=$(sh_quote /usr/bin/printf '%s\0' "${given[@]}")
came=()
while IFS= read -r -d '' arg; do came+=("$arg"); done < <(/bin/sh -c "$line")
[ "${#came[@]}" -eq "${#given[@]}" ] || { echo "FAIL: ${#given[@]} arguments given, ${#came[@]} came through /bin/sh"; exit 1; }
for k in "${!given[@]}"; do
    [ "${came[k]}" = "${given[k]}" ] || { echo "FAIL: '${given[k]}' came through /bin/sh as '${came[k]}'"; exit 1; }
done
echo "Cluster: ${#given[@]} awkward arguments came through /bin/sh as given"
