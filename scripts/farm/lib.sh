# lib.sh - shared by the farm scripts (sourced, POSIX sh): the waterworld binary, the two
# commands a farm needs from it (the slice job lines, and join), and the byte comparisons that
# hold a farmed render or sweep to one process.
#
#   . scripts/farm/lib.sh
#   farm_render_jobs DIR N SCENE [render options]   N command lines on stdout, one per slice
#   farm_join DIR                                   join a render's or a sweep's DIR
#   farm_same_render REF DIR                        frames and sound track byte for byte
#   farm_same_sweep REF DIR                         sweep.jsonl, .csv, thumbnails byte for byte
#
# Environment: WW_BIN (default ./waterworld, else the one on PATH). The functions' own variables
# start with an underscore (sh has no locals): a script sourcing this keeps its names.

farm_ww() {
    _w=${WW_BIN:-./waterworld}
    [ -x "$_w" ] || _w=$(command -v waterworld || true)
    [ -n "$_w" ] || { echo "farm: no waterworld binary (build it with make, or set WW_BIN)" >&2; return 3; }
    # absolute, so that the job lines run from any folder and on any node of a shared filesystem
    case "$_w" in /*) ;; */*) _w="$(cd "$(dirname "$_w")" && pwd)/$(basename "$_w")" ;; esac
    echo "$_w"
}

# the joined sound track in a render's DIR (--audio with --slice names a file inside DIR)
FARM_AUDIO=audio.wav

# the job lines of a render cut into N slices (render --slices N --emit-jobs), each writing its
# part of the sound track to be joined into DIR/audio.wav
farm_render_jobs() {
    _d=$1 _n=$2
    shift 2
    "$(farm_ww)" render "$@" -o "$_d" --audio "$FARM_AUDIO" --slices "$_n" --emit-jobs
}

# join a render's slices or a sweep's points; lists what is missing and exits 1 when incomplete
farm_join() {
    "$(farm_ww)" join "$1"
}

# every frame of REF is in DIR with the same bytes, and no more frames; the sound tracks equal
farm_same_render() {
    _bad=0 _n=0
    for _f in "$1"/frame_*.png; do
        _n=$((_n + 1))
        cmp -s "$_f" "$2/${_f##*/}" || { echo "farm: ${_f##*/} differs from one process" >&2; _bad=1; }
    done
    _m=$(ls "$2" | grep -c '^frame_.*\.png$')
    [ "$_m" -eq "$_n" ] || { echo "farm: $_m frames in $2, $_n in one process" >&2; _bad=1; }
    cmp -s "$1/$FARM_AUDIO" "$2/$FARM_AUDIO" ||
        { echo "farm: $2/$FARM_AUDIO differs from one process" >&2; _bad=1; }
    [ "$_bad" = 0 ] && echo "  same bytes: $_n frames and $FARM_AUDIO ($(wc -c <"$2/$FARM_AUDIO") bytes)"
    return "$_bad"
}

# sweep.jsonl, sweep.csv, the contact sheet and every thumbnail the same bytes as one process's
farm_same_sweep() {
    _bad=0 _n=0
    for _f in sweep.jsonl sweep.csv contact_sheet.png; do
        [ -e "$1/$_f" ] || continue
        cmp -s "$1/$_f" "$2/$_f" || { echo "farm: $_f differs from one process" >&2; _bad=1; }
    done
    for _f in "$1"/thumbs/point_*.png; do
        [ -e "$_f" ] || continue
        _n=$((_n + 1))
        cmp -s "$_f" "$2/thumbs/${_f##*/}" || { echo "farm: thumbs/${_f##*/} differs" >&2; _bad=1; }
    done
    [ "$_bad" = 0 ] && echo "  same bytes: sweep.jsonl ($(wc -l <"$2/sweep.jsonl") points), sweep.csv, contact sheet, $_n thumbnails"
    return "$_bad"
}

# one word quoted for sh: 'it'\''s'
farm_q() {
    printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"
}
