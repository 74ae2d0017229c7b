#!/usr/bin/env bash
# An animated WebP made by raster's exporters as two VP9 WebM videos, with Debian's ffmpeg (which
# cannot decode animated WebP, so webp-frames hands it the frames as PNG):
#   BASE-lossless.webm  VP9 profile 1, planar RGB (gbrp, 4:4:4), lossless: decodes to exactly the
#                       WebP's pixels (YUV 4:4:4 would not: the colour conversion rounds)
#   BASE.webm           VP9 profile 0, yuv420p, CRF 4: what Safari (and every browser) plays
# at the WebP's own frame rate. Outputs are never replaced: each is encoded to a temporary file
# beside it and linked into place only if the name is still free.
set -euo pipefail

program=make-webm
usage() {
    cat <<'TXT'
usage: tools/make-webm.sh FILE.webp [OUT_BASENAME]
Writes OUT_BASENAME-lossless.webm (VP9 RGB 4:4:4, lossless, bit-exact) and OUT_BASENAME.webm
(VP9 4:2:0, plays in Safari) from an animated WebP whose frames last equally long.
OUT_BASENAME defaults to FILE without .webp. Needs ffmpeg (apt-get install ffmpeg) and
raster's webp-frames (found beside this script's build, on PATH, or as $RASTER_WEBP_FRAMES).
TXT
}
fail() {
    echo "$program: $1" >&2
    exit 1
}
usage_error() {
    echo "$program: $1 (see --help)" >&2
    exit 2
}

case "${1:-}" in
-h | --help)
    usage
    exit 0
    ;;
esac
[ $# -ge 1 ] && [ $# -le 2 ] || usage_error "expected FILE.webp and at most an OUT_BASENAME"
input="$1"
base="${2:-${input%.[wW][eE][bB][pP]}}"
lossless="$base-lossless.webm"
safari="$base.webm"

ffmpeg="${FFMPEG:-ffmpeg}"
command -v "$ffmpeg" >/dev/null 2>&1 || fail "ffmpeg is not installed; on Debian: sudo apt-get install ffmpeg"

here="$(cd "$(dirname "$0")/.." && pwd)"
frames_tool="${RASTER_WEBP_FRAMES:-}"
if [ -z "$frames_tool" ]; then
    for candidate in "$here/build/release/bin/webp-frames" "$here/build/apps/bin/webp-frames" "$(command -v webp-frames || true)"; do
        if [ -n "$candidate" ] && [ -x "$candidate" ]; then
            frames_tool="$candidate"
            break
        fi
    done
fi
[ -n "$frames_tool" ] && [ -x "$frames_tool" ] ||
    fail "webp-frames not found: build it (cmake --build --preset release --target webp-frames) or set RASTER_WEBP_FRAMES"

[ -e "$input" ] || fail "'$input' does not exist"
[ -f "$input" ] || fail "'$input' is not a regular file"
[ "$(head -c 4 -- "$input")" = RIFF ] && [ "$(dd if="$input" bs=1 skip=8 count=4 2>/dev/null)" = WEBP ] ||
    fail "'$input' is not a WebP file"
for output in "$lossless" "$safari"; do
    [ ! -e "$output" ] && [ ! -L "$output" ] || fail "'$output' exists; remove it or give another OUT_BASENAME"
done
out_dir="$(dirname -- "$base")"
[ -d "$out_dir" ] && [ -w "$out_dir" ] || fail "cannot write into '$out_dir'"

work="$(mktemp -d "${TMPDIR:-/tmp}/make-webm.XXXXXX")"
pending=()
cleanup() {
    rm -rf -- "$work"
    [ ${#pending[@]} -eq 0 ] || rm -f -- "${pending[@]}"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

report="$("$frames_tool" -- "$input" "$work/frames")" || exit 1
# "Wrote DIR/0000.png to 0359.png: 360 frames of 800x600, 20 ms each, 12345 bytes"
frames="$(sed -n 's/.*: \([0-9]*\) frames of .*/\1/p' <<<"$report")"
size="$(sed -n 's/.* frames of \([0-9]*x[0-9]*\),.*/\1/p' <<<"$report")"
spacing="$(sed -n 's/.*, \([0-9]*\) ms each,.*/\1/p' <<<"$report")"
[ -n "$frames" ] && [ -n "$size" ] || fail "cannot read webp-frames' report: $report"
[ "$frames" -ge 2 ] || fail "'$input' is a still, not an animation"
if [ -z "$spacing" ]; then
    timing="$(sed -n 's/.*, lasting \([0-9]* to [0-9]* ms\),.*/\1/p' <<<"$report")"
    fail "'$input' has frames lasting $timing; a video needs one frame rate"
fi

# -framerate 1000/SPACING: the WebP's milliseconds exactly, 50 fps for the exporters' default.
encode() {  # encode OUTPUT FFMPEG-OPTIONS...: to a temporary file beside OUTPUT, then linked into place
    local output="$1" temporary
    shift
    temporary="$(mktemp "$(dirname -- "$output")/.$(basename -- "$output").XXXXXX")"
    pending+=("$temporary")
    "$ffmpeg" -nostdin -hide_banner -loglevel error -y -framerate "1000/$spacing" -i "$work/frames/%04d.png" \
        -c:v libvpx-vp9 "$@" -an -f webm "$temporary" || fail "ffmpeg could not encode '$output'"
    chmod "$(printf '%o' $((0666 & ~0$(umask))))" -- "$temporary"  # mktemp's 0600, opened up as a new file would be
    ln -- "$temporary" "$output" 2>/dev/null || fail "'$output' appeared while encoding; left it alone"
    rm -f -- "$temporary"
    echo "Wrote $output: $(stat -c %s -- "$output") bytes"
}

encode "$lossless" -pix_fmt gbrp -lossless 1 -cpu-used 2 -row-mt 1
# Tagged BT.709 (limited range), converted with that matrix, so players put the colours back.
encode "$safari" -vf scale=out_color_matrix=bt709:out_range=tv -pix_fmt yuv420p -colorspace bt709 -color_primaries bt709 \
    -color_trc bt709 -color_range tv -crf 4 -b:v 0 -deadline best -row-mt 1
echo "$program: $frames frames of $size at 1000/$spacing fps, $((frames * spacing)) ms"
