#!/usr/bin/env bash
# make-video.sh - a scene into an H.264 MP4 (yuv420p, tagged BT.709 limited range), with its
# sound track muxed as AAC when the scene has one (`waterworld plan SCENE` prints an "audio:"
# line). Frames go as a Y4M stream straight into ffmpeg, never through files on disk.
#
#   scripts/make-video.sh SCENE.yaml OUT.mp4 [render options, e.g. --frames 90 --size 640x360]
#   scripts/make-video.sh --from-dir DIR OUT.mp4
#
# --from-dir: the video of a render made in slices (`render --slice I/N -o DIR`, PNG frames):
# `waterworld join DIR` first (it lists what is missing and stops, exit 1), then DIR's frames
# and the joined sound track (when the slices made one) into OUT.mp4. The frame rate and the
# first frame come from DIR/slices/slice_00000.record.
#
# Environment: WW_BIN (the waterworld binary, default ./waterworld, else the one on PATH),
# MAKE_VIDEO_CRF (x264 quality, default 18), MAKE_VIDEO_PRESET (x264 preset, default medium).
# OUT.mp4 appears only when complete (written beside it under a temporary name, then moved).
# Exit: 0 done, 2 usage, 3 ffmpeg missing, else the status of the step that failed.
set -euo pipefail

usage() { echo "usage: make-video.sh SCENE.yaml OUT.mp4 [render options] | --from-dir DIR OUT.mp4" >&2; exit 2; }
[ $# -ge 2 ] || usage
from_dir=
if [ "$1" = --from-dir ]; then
    [ $# -eq 3 ] || usage
    from_dir=$2
    shift
fi
scene=$1
out=$2
shift 2
case "$out" in -*) usage ;; esac

ww=${WW_BIN:-./waterworld}
if [ ! -x "$ww" ]; then ww=$(command -v waterworld || true); fi
[ -n "$ww" ] || { echo "make-video.sh: no waterworld binary (build it with make, or set WW_BIN)" >&2; exit 3; }
command -v ffmpeg >/dev/null 2>&1 ||
    { echo "make-video.sh: ffmpeg is not installed (Debian: apt-get install ffmpeg)" >&2; exit 3; }

x264=(-c:v libx264 -preset "${MAKE_VIDEO_PRESET:-medium}" -crf "${MAKE_VIDEO_CRF:-18}"
      -pix_fmt yuv420p -colorspace bt709 -color_primaries bt709 -color_trc bt709 -color_range tv)

if [ -n "$from_dir" ]; then
    "$ww" join "$from_dir" >/dev/null || exit $?
    rec=$from_dir/slices/slice_00000.record
    field() { sed -n "s/^$1 //p" "$rec"; }
    fps=$(field fps)
    first=$(field frames | cut -d: -f1)
    track=$(field audio)
    [ "$(field format)" = png ] ||
        { echo "make-video.sh: $from_dir holds $(field format) frames: the video is made from png" >&2; exit 2; }
    tmp=$(mktemp -d "$(dirname -- "$out")/.make-video.XXXXXX")
    trap 'rm -rf -- "$tmp"' EXIT
    trap 'exit 130' INT TERM
    sound=()
    [ "$track" = - ] || sound=(-i "$from_dir/$track" -map 0:v -map 1:a -c:a aac -b:a 192k -shortest)
    ffmpeg -hide_banner -loglevel error -framerate "$fps" -start_number "$first" \
        -i "$from_dir/frame_%05d.png" "${sound[@]}" -vf scale=out_color_matrix=bt709:out_range=tv \
        "${x264[@]}" -movflags +faststart -f mp4 "$tmp/out.mp4"
    mv -f -- "$tmp/out.mp4" "$out"
    echo "make-video.sh: $out from $from_dir ($([ "$track" = - ] && echo "video, no sound track" || echo "video + sound"))" >&2
    exit 0
fi

# plan sees the same scene: the render options that change it (--set, --script) are passed on
plan_args=()
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
    case "${args[i]}" in
    --set | --script) plan_args+=("${args[i]}" "${args[i + 1]:-}"); i=$((i + 1)) ;;
    esac
done
plan=$("$ww" plan "$scene" "${plan_args[@]}") || exit $?
audio=0
case "$plan" in audio:* | *$'\n'audio:*) audio=1 ;; esac

# the temporary folder sits beside OUT so that the final mv is a rename
tmp=$(mktemp -d "$(dirname -- "$out")/.make-video.XXXXXX")
trap 'rm -rf -- "$tmp"' EXIT
trap 'exit 130' INT TERM

if [ "$audio" = 1 ]; then
    # the WAV is complete only when the render ends: encode the video, then mux (no re-encode)
    "$ww" render "$scene" --format y4m -o - --audio "$tmp/audio.wav" "$@" |
        ffmpeg -hide_banner -loglevel error -f yuv4mpegpipe -i - "${x264[@]}" -an "$tmp/video.mp4"
    ffmpeg -hide_banner -loglevel error -i "$tmp/video.mp4" -i "$tmp/audio.wav" -map 0:v -map 1:a \
        -c:v copy -c:a aac -b:a 192k -shortest -movflags +faststart "$tmp/out.mp4"
else
    "$ww" render "$scene" --format y4m -o - "$@" |
        ffmpeg -hide_banner -loglevel error -f yuv4mpegpipe -i - "${x264[@]}" -movflags +faststart \
            "$tmp/out.mp4"
fi
mv -f -- "$tmp/out.mp4" "$out"
echo "make-video.sh: $out ($([ "$audio" = 1 ] && echo "video + sound" || echo "video, no sound track"))" >&2
