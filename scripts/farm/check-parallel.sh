#!/bin/sh
# check-parallel.sh WORK - a render with sound in 3 slices and a 4-point sweep with thumbnails,
# each run as job lines through GNU parallel and joined, held byte for byte to one process; the
# render first without one slice, which join must list and re-run.
# `make test` runs it (farm_parallel_matches_one_process in tests/test_farm.c).
#
# Environment: WW_BIN (the binary), FARM_SCENE (default scenes/lake.yaml: it has a sound
# track), FARM_SIZE (160x90), FARM_FRAMES (9). Each task runs with LP_NUM_THREADS=1.
# Exit: 0 same bytes, 1 a difference or a failed job, 77 GNU parallel is not installed.
set -eu
here=$(dirname "$0")
. "$here/lib.sh"

[ $# -eq 1 ] || { echo "usage: check-parallel.sh WORK" >&2; exit 2; }
command -v parallel >/dev/null 2>&1 ||
    { echo "check-parallel: GNU parallel is not installed (Debian: apt-get install parallel)" >&2; exit 77; }
work=$1
scene=$(cd "$(dirname "${FARM_SCENE:-scenes/lake.yaml}")" && pwd)/$(basename "${FARM_SCENE:-scenes/lake.yaml}")
size=${FARM_SIZE:-160x90}
frames=${FARM_FRAMES:-9}
ww=$(farm_ww)
export LP_NUM_THREADS=1
mkdir -p "$work"

echo "render: $scene, $frames frames at $size with its sound track, 3 slices through parallel -j 2"
mkdir -p "$work/one"
"$ww" render "$scene" --size "$size" --frames "0:$frames" -o "$work/one" --audio "$work/one/$FARM_AUDIO" --quiet
farm_render_jobs "$work/par" 3 "$scene" --size "$size" --frames "0:$frames" --quiet >"$work/render.jobs"
# slice 1 left out, as if its node had died: join lists it and prints the command that
# completes the set, which parallel runs; then the join succeeds
sed 2d "$work/render.jobs" | parallel --will-cite -j 2 --joblog "$work/render.joblog"
if farm_join "$work/par" >"$work/rerun.jobs" 2>"$work/join.err"; then
    echo "check-parallel: join succeeded with slice 1 missing" >&2
    exit 1
fi
grep -q "^slice 1/3: missing" "$work/join.err" && [ "$(wc -l <"$work/rerun.jobs")" -eq 1 ] ||
    { echo "check-parallel: join did not name the one missing slice:" >&2; cat "$work/join.err" "$work/rerun.jobs" >&2; exit 1; }
echo "  slice 1 missing: join exit 1, \"$(head -n 1 "$work/join.err")\"; its command re-run through parallel"
parallel --will-cite -j 1 <"$work/rerun.jobs"
farm_join "$work/par"
farm_same_render "$work/one" "$work/par"

echo "sweep: 4 points with thumbnails through parallel -j 2"
set -- "$scene" --vary 'water.waves.list[0].amplitude=0.1:0.4:2' --vary 'water.waves.list[1].wavelength=3,5' \
    --thumbs --thumb-size 64x36 --quiet
"$ww" sweep "$@" -o "$work/sweep-one"
"$ww" sweep "$@" -o "$work/sweep-par" --emit-jobs >"$work/sweep.jobs"
parallel --will-cite -j 2 --joblog "$work/sweep.joblog" <"$work/sweep.jobs"
farm_join "$work/sweep-par"
farm_same_sweep "$work/sweep-one" "$work/sweep-par"
