#!/usr/bin/env bash
# tools/tag-releases.sh in a fresh clone gives every CHANGELOG version a tag, and is idempotent.
# Exits 77 (skipped) outside a full git checkout.
set -euo pipefail
source_dir="$1"
git -C "$source_dir" rev-parse --git-dir >/dev/null 2>&1 || exit 77
[ "$(git -C "$source_dir" rev-parse --is-shallow-repository)" = false ] || exit 77
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q --no-tags "$source_dir" "$work/clone"
cd "$work/clone"
git tag -l | grep -q . && { echo "a --no-tags clone already has tags"; exit 1; }
tools/tag-releases.sh >/dev/null
versions=$(sed -n 's/^## \[\([0-9.]*\)\].*/\1/p' CHANGELOG.md)
for version in $versions; do
    git rev-parse -q --verify "refs/tags/v$version" >/dev/null || { echo "no tag v$version"; exit 1; }
done
[ "$(git rev-parse v0.0.1)" = "$(git rev-parse v0.0.7)" ] || { echo "0.0.1 to 0.0.7 should share a commit"; exit 1; }
for version in $versions; do
    case "$version" in 0.0.*) continue ;; esac
    subject=$(git log -1 --format=%s "v$version")
    [[ "$subject" == "Release $version"* || "$subject" =~ \(releases\ [0-9.]+\ to\ [0-9.]+\) ]] ||
        { echo "v$version is not on a 'Release $version' commit nor on one naming a range"; exit 1; }
done
[ -z "$(tools/tag-releases.sh)" ] || { echo "a second run should tag nothing"; exit 1; }
echo "tagged: $(git tag -l | tr '\n' ' ')"
