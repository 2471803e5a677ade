#!/bin/sh
# bench.sh [WORK] - the farm's speed-up on this machine: a render (FARM_SCENE, default
# scenes/lake.yaml, FARM_FRAMES 60 frames at FARM_SIZE 640x360, with its sound track) and a
# 16-point sweep with 160x90 thumbnails, each as one process and as job lines through
# `parallel -j1` and `-j2` (4 render slices), LP_NUM_THREADS=1 per task, FARM_REPEAT (2) times.
# Wall seconds per run; every farmed result is checked against one process's bytes.
set -eu
here=$(dirname "$0")
. "$here/lib.sh"
work=${1:-$(mktemp -d /tmp/ww-farm-bench.XXXXXX)}
scene=$(pwd)/${FARM_SCENE:-scenes/lake.yaml}
frames=${FARM_FRAMES:-60} size=${FARM_SIZE:-640x360} repeat=${FARM_REPEAT:-2}
ww=$(farm_ww)
export LP_NUM_THREADS=1
now() { date +%s.%N; }
secs() { echo "$1 $2" | awk '{printf "%.2f", $2 - $1}'; }
sweep="--vary water.waves.list[0].amplitude=0.1:0.4:4 --vary water.waves.list[1].wavelength=2:5:4 --thumbs --quiet"
echo "machine: $(nproc) CPUs, load $(cut -d' ' -f1-3 /proc/loadavg)"
r=1
while [ "$r" -le "$repeat" ]; do
    rm -rf "$work"/*
    mkdir -p "$work/one"
    t=$(now)
    "$ww" render "$scene" --size "$size" --frames "0:$frames" -o "$work/one" --audio "$work/one/$FARM_AUDIO" --quiet
    line="run $r: render $frames frames $size: one process $(secs "$t" "$(now)") s"
    for j in 1 2; do
        farm_render_jobs "$work/j$j" 4 "$scene" --size "$size" --frames "0:$frames" --quiet >"$work/j$j.jobs"
        t=$(now)
        parallel --will-cite -j "$j" <"$work/j$j.jobs"
        farm_join "$work/j$j" 2>/dev/null
        line="$line, parallel -j$j $(secs "$t" "$(now)") s"
        farm_same_render "$work/one" "$work/j$j" >/dev/null
    done
    echo "$line"
    t=$(now)
    # shellcheck disable=SC2086
    "$ww" sweep "$scene" $sweep -o "$work/sweep-one"
    line="run $r: sweep 16 points + thumbnails: one process $(secs "$t" "$(now)") s"
    for j in 1 2; do
        # shellcheck disable=SC2086
        "$ww" sweep "$scene" $sweep -o "$work/sweep-j$j" --emit-jobs >"$work/sweep-j$j.jobs"
        t=$(now)
        parallel --will-cite -j "$j" <"$work/sweep-j$j.jobs"
        farm_join "$work/sweep-j$j" 2>/dev/null
        line="$line, parallel -j$j $(secs "$t" "$(now)") s"
        farm_same_sweep "$work/sweep-one" "$work/sweep-j$j" >/dev/null
    done
    echo "$line"
    r=$((r + 1))
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
