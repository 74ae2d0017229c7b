#!/usr/bin/env bash
# tools/make-webm.sh on a short animation from animated-cube: the lossless WebM decodes to the
# renderer's own frames (written by --frames-dir) byte for byte; the Safari one is VP9 profile 0
# yuv420p with every frame at 50 fps; and every mistake is one line with the right exit code.
# Usage: make_webm_test.sh SOURCE_DIR ANIMATED_CUBE WEBP_FRAMES. Exits 77 (skipped) without ffmpeg.
set -euo pipefail
source_dir="$1"
animated_cube="$2"
export RASTER_WEBP_FRAMES="$3"
make_webm="$source_dir/tools/make-webm.sh"
if ! command -v ffmpeg >/dev/null || ! command -v ffprobe >/dev/null; then
    echo "SKIP: ffmpeg and ffprobe are not installed (apt-get install ffmpeg)"
    exit 77
fi
work="$(mktemp -d)"
trap 'rm -rf -- "$work"' EXIT
cd "$work"
status=0
check() {  # check DESCRIPTION EXPECTED ACTUAL
    if [ "$2" != "$3" ]; then
        echo "FAIL: $1: expected '$2', got '$3'"
        status=1
    fi
}

frames=6 width=160 height=120
"$animated_cube" --quiet --frames "$frames" --width "$width" --height "$height" spin.webp
"$animated_cube" --quiet --frames "$frames" --width "$width" --height "$height" --frames-dir rendered

umask 022
bash "$make_webm" spin.webp out >log 2>&1 || { cat log; echo "FAIL: make-webm exited $?"; exit 1; }
cat log
check "files written" "out-lossless.webm out.webm spin.webp" "$(ls -- *.webm *.webp | tr '\n' ' ' | sed 's/ $//')"
check "no temporary files left" "" "$(ls -A | grep '^\.' || true)"
check "modes as the umask gives new files" "644 644" "$(stat -c %a out-lossless.webm out.webm | tr '\n' ' ' | sed 's/ $//')"

# Lossless: every decoded frame is the renderer's, byte for byte.
ffmpeg -v error -i out-lossless.webm -f rawvideo -pix_fmt rgb24 decoded.rgb
ffmpeg -v error -i rendered/%04d.png -f rawvideo -pix_fmt rgb24 rendered.rgb
check "rendered frames' bytes" "$((frames * width * height * 3))" "$(stat -c %s rendered.rgb)"
if ! cmp -s decoded.rgb rendered.rgb; then
    echo "FAIL: the lossless WebM is not the rendered frames: $(cmp decoded.rgb rendered.rgb | head -1)"
    status=1
fi
probe() {  # probe FILE ENTRIES
    ffprobe -v error -count_frames -select_streams v:0 -show_entries "$2" -of default=noprint_wrappers=1:nokey=1 "$1" | tr '\n' ' ' | sed 's/ $//'
}
check "lossless stream" "vp9 Profile 1 gbrp $frames" "$(probe out-lossless.webm stream=codec_name,profile,pix_fmt,nb_read_frames)"

# Safari's: VP9 profile 0, 4:2:0, 50 fps, six frames of 20 ms.
check "4:2:0 stream" "vp9 Profile 0 yuv420p 50/1 $frames" "$(probe out.webm stream=codec_name,profile,pix_fmt,r_frame_rate,nb_read_frames)"
check "4:2:0 duration" "0.120000" "$(probe out.webm format=duration)"
check "lossless duration" "0.120000" "$(probe out-lossless.webm format=duration)"
# Close, not exact: colour at half resolution smears the cube's saturated edges over black (a
# frame's mean squared error measured 20 to 58 at this size, nearly all of it in blue at the
# edges). A wrong colour matrix, range or frame order would be far beyond 80.
ffmpeg -v error -i out.webm -framerate 50 -i rendered/%04d.png \
    -lavfi "[0:v]format=rgb24[a];[1:v]format=rgb24[b];[a][b]psnr=stats_file=psnr.log" -f null -
worst="$(awk -F'[ :]' '{for (i = 1; i <= NF; i++) if ($i == "mse_avg") print $(i + 1)}' psnr.log | sort -g | tail -1)"
check "frames compared" "$frames" "$(wc -l <psnr.log)"
echo "4:2:0: the worst frame's mean squared error against the renderer is $worst"
awk -v mse="$worst" 'BEGIN { exit !(mse != "" && mse < 80) }' || { echo "FAIL: 4:2:0 frames too far from the renderer (mse $worst)"; status=1; }

# Mistakes: one line each, exit 1 (2 for usage), nothing replaced.
expect_error() {  # expect_error CODE MESSAGE ARGUMENTS...
    local code="$1" message="$2" got=0
    shift 2
    bash "$make_webm" "$@" >out.txt 2>err.txt || got=$?
    check "exit code of make-webm $*" "$code" "$got"
    check "message of make-webm $*" "$message" "$(cat err.txt)"
    check "lines of make-webm $*" "1" "$(wc -l <err.txt)"
}
before="$(md5sum out.webm out-lossless.webm)"
expect_error 1 "make-webm: 'out-lossless.webm' exists; remove it or give another OUT_BASENAME" spin.webp out
check "outputs untouched" "$before" "$(md5sum out.webm out-lossless.webm)"
expect_error 1 "make-webm: 'missing.webp' does not exist" missing.webp
printf 'not a picture at all' >fake.webp
expect_error 1 "make-webm: 'fake.webp' is not a WebP file" fake.webp
"$animated_cube" --quiet --frames 1 --width 8 --height 8 one.webp
expect_error 1 "make-webm: 'one.webp' is a still, not an animation" one.webp
FFMPEG=/nonexistent/ffmpeg expect_error 1 "make-webm: ffmpeg is not installed; on Debian: sudo apt-get install ffmpeg" spin.webp other
expect_error 2 "make-webm: expected FILE.webp and at most an OUT_BASENAME (see --help)"
check "nothing else written" "fake.webp one.webp out-lossless.webm out.webm spin.webp" "$(ls -- *.webm *.webp | tr '\n' ' ' | sed 's/ $//')"
[ "$status" -eq 0 ] && echo "make-webm: all checks passed"
exit "$status"
