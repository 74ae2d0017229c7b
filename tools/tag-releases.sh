#!/usr/bin/env bash
# Creates a vX.Y.Z tag for every release in this clone's history, so consumers can pin one.
set -euo pipefail

usage() {
    cat <<'TXT'
usage: tools/tag-releases.sh [--dry-run]
  Tags each commit whose subject starts with "Release X.Y.Z" as vX.Y.Z. A commit whose subject
  says "(releases A to B)" gets a tag for every CHANGELOG version from A to B: 0.0.1 to 0.0.7
  share one commit, and so do 0.1.2 to 0.1.11. Versions come from CHANGELOG.md. Existing tags
  are never moved.
  --dry-run  print what would be tagged, change nothing
TXT
}

dry_run=0
case "${1:-}" in
"") ;;
--dry-run) dry_run=1 ;;
-h | --help) usage; exit 0 ;;
*) usage >&2; exit 2 ;;
esac

cd "$(dirname "$0")/.."
if [ "$(git rev-parse --is-shallow-repository)" = true ]; then
    echo "tag-releases: this clone is shallow; run 'git fetch --unshallow' first" >&2
    exit 1
fi

# Every version in the changelog, oldest first.
mapfile -t versions < <(sed -n 's/^## \[\([0-9]*\.[0-9]*\.[0-9]*\)\].*/\1/p' CHANGELOG.md | sort -V)

tag() {  # version commit
    local existing
    if existing=$(git rev-parse -q --verify "refs/tags/v$1^{commit}"); then
        [ "$existing" = "$(git rev-parse "$2^{commit}")" ] ||
            echo "tag-releases: v$1 already names ${existing:0:7}, not ${2:0:7}; left alone" >&2
        return
    fi
    echo "v$1 $(git log -1 --format='%h %s' "$2")"
    [ "$dry_run" -eq 1 ] || git tag "v$1" "$2"
}

while read -r commit subject; do
    if [[ "$subject" =~ \(releases\ ([0-9]+\.[0-9]+\.[0-9]+)\ to\ ([0-9]+\.[0-9]+\.[0-9]+)\) ]]; then
        first="${BASH_REMATCH[1]}" last="${BASH_REMATCH[2]}"
        for version in "${versions[@]}"; do
            if [ "$(printf '%s\n' "$first" "$version" | sort -V | head -1)" = "$first" ] &&
                [ "$(printf '%s\n' "$version" "$last" | sort -V | head -1)" = "$version" ]; then
                tag "$version" "$commit"
            fi
        done
    elif [[ "$subject" =~ ^Release\ ([0-9]+\.[0-9]+\.[0-9]+) ]]; then
        tag "${BASH_REMATCH[1]}" "$commit"
    fi
done < <(git log --reverse --format='%H %s' HEAD)
