#!/bin/sh
# parallel.sh DIR JOBS [GNU parallel options] - run the job lines of a render or a sweep (what
# `--emit-jobs` printed into the file JOBS) with GNU parallel, then join DIR.
#
#   waterworld render scenes/lake.yaml --size 1280x720 --audio audio.wav -o out/lake \
#       --slices 16 --emit-jobs > out/lake.jobs
#   scripts/farm/parallel.sh out/lake out/lake.jobs -j 2                  # this machine
#   scripts/farm/parallel.sh out/lake out/lake.jobs -S 8/node1,8/node2    # over ssh
#
# Over ssh every node must see the binary, the scene and DIR at the paths the job lines name
# (a shared filesystem: NFS, CephFS, ...); docs/farm.md has the way without one.
# The joblog is DIR/parallel.joblog. When it is there from an earlier run, only the lines that
# failed or never ran run again (--resume-failed), then the join is tried again.
# Exit: the join's (0 complete; 1 slices missing: it lists them) or parallel's when jobs failed.
set -eu
[ $# -ge 2 ] || { echo "usage: parallel.sh DIR JOBS [parallel options]" >&2; exit 2; }
dir=$1 jobs=$2
shift 2
. "$(dirname "$0")/lib.sh"
command -v parallel >/dev/null 2>&1 ||
    { echo "parallel.sh: GNU parallel is not installed (Debian: apt-get install parallel)" >&2; exit 3; }
mkdir -p "$dir"
log=$dir/parallel.joblog
resume=""
[ -s "$log" ] && resume=--resume-failed
# LP_NUM_THREADS: llvmpipe's threads per task (default 1: the tasks are the parallelism), carried
# to the ssh logins too (--env)
export LP_NUM_THREADS="${LP_NUM_THREADS:-1}"
parallel --will-cite --env LP_NUM_THREADS --joblog "$log" $resume "$@" <"$jobs" || {
    rc=$?
    echo "parallel.sh: $rc job(s) failed (see $log); run the same command again to re-run them" >&2
    exit "$rc"
}
farm_join "$dir"
