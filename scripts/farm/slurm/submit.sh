#!/bin/sh
# submit.sh - a render or a sweep as a Slurm job array and its join, one command.
#
#   scripts/farm/slurm/submit.sh render DIR N SCENE [render options]   N slices, then join DIR
#   scripts/farm/slurm/submit.sh sweep DIR SCENE --vary ... [options]  a task per point, then join
#
# Options first: --array LIST re-runs only those tasks (e.g. 3,7 after a failure: the join
# lists them), --sbatch 'OPTIONS' adds sbatch options to every job (--partition=..., --time=...),
# --checkpoint-every K (render) first submits one job that simulates the scene and writes a
# checkpoint every K steps into DIR/checkpoints, and the slices, started after it (afterok),
# each load the latest checkpoint at or before their first frame instead of simulating their
# prefix (pick K as the steps of a slice or a divisor of it).
# The join job waits for the array with --dependency=afterany: it runs even when a task failed,
# and then lists the missing slices. Prints "array ID join ID". Logs go to DIR/logs/.
# Environment: WW_BIN (the binary; its absolute path goes into the jobs), LP_NUM_THREADS.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
. "$here/lib.sh"
array="" extra="" every=""
while [ $# -gt 0 ]; do
    case "$1" in
    --array) array=$2; shift 2 ;;
    --checkpoint-every) every=$2; shift 2 ;;
    --sbatch) extra=$2; shift 2 ;;
    *) break ;;
    esac
done
[ $# -ge 3 ] || { sed -n '2,16p' "$0" >&2; exit 2; }
kind=$1 dir=$2
shift 2
WW_BIN=$(farm_ww) || exit 3
export WW_BIN
mkdir -p "$dir/logs"
dir=$(cd "$dir" && pwd)
case "$kind" in
render)
    n=$1
    shift
    after=""
    if [ -n "$every" ]; then
        # the simulation sees the scene the render sees: its --frames, --set and --script
        sim=$(farm_q "$1")
        i=2
        while [ "$i" -le $# ]; do
            eval "w=\${$i}"
            case "$w" in
            --frames | --set | --script) i=$((i + 1)); eval "v=\${$i}"; sim="$sim $w $(farm_q "$v")" ;;
            esac
            i=$((i + 1))
        done
        # shellcheck disable=SC2086
        ck=$(eval "sbatch --parsable $extra --output=$(farm_q "$dir/logs/%x-%j.out")" \
            "$(farm_q "$here/slurm/checkpoints.sbatch") $sim --checkpoint-every $(farm_q "$every")" \
            "-o $(farm_q "$dir/checkpoints")")
        ck=${ck%%;*}
        after="--dependency=afterok:$ck"
        set -- "$@" --checkpoints "$dir/checkpoints"
    fi
    # the job lines are made once, here: every task reads its own line
    farm_render_jobs "$dir" "$n" "$@" >"$dir/render.jobs"
    n=$(wc -l <"$dir/render.jobs")
    script=$here/slurm/render.sbatch
    set -- "$dir/render.jobs"
    ;;
sweep)
    n=$("$WW_BIN" sweep "$@" -o "$dir" --emit-jobs | wc -l)
    script=$here/slurm/sweep.sbatch
    set -- "$@" -o "$dir"
    ;;
*) echo "submit.sh: render or sweep, not '$kind'" >&2; exit 2 ;;
esac
[ "$n" -ge 1 ] || { echo "submit.sh: no tasks" >&2; exit 2; }
# shellcheck disable=SC2086
id=$(sbatch --parsable $extra ${after:-} --array="${array:-0-$((n - 1))}" \
    --output="$dir/logs/%x-%A_%a.out" "$script" "$@")
id=${id%%;*}
# shellcheck disable=SC2086
join=$(sbatch --parsable $extra --dependency="afterany:$id" \
    --output="$dir/logs/%x-%j.out" "$here/slurm/join.sbatch" "$dir")
echo "${ck:+checkpoints $ck }array ${id} join ${join%%;*}"
