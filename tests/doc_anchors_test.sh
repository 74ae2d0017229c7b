#!/usr/bin/env bash
# Every conventions.md#anchor that a header or a document links to is a heading there, by the
# slug GitHub makes (lower case, spaces to hyphens); no {#id} attributes, which GitHub ignores.
set -euo pipefail
cd "$1"
slugs=$(sed -n 's/^##* //p' doc/conventions.md | tr '[:upper:]' '[:lower:]' | sed 's/[^a-z0-9 -]//g; s/ /-/g')
status=0
if grep -n '{#' doc/*.md README.md; then echo "GitHub ignores {#id} anchors"; status=1; fi
for anchor in $(grep -rhoE 'conventions\.md#[a-z0-9-]+' include src apps doc README.md | sed 's/.*#//' | sort -u); do
    grep -qx -- "$anchor" <<<"$slugs" || { echo "conventions.md#$anchor names no heading"; status=1; }
done
# Every test named in conventions.md exists.
for name in $(grep -oE '`[A-Z][A-Za-z]+\.[A-Z][A-Za-z]+`' doc/conventions.md | tr -d '`' | sort -u); do
    grep -rqE "TEST(_P|_F)?\(${name%%.*}, ${name#*.}\)" tests || { echo "conventions.md names missing test $name"; status=1; }
done
exit $status
