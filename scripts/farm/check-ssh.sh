#!/bin/sh
# check-ssh.sh [WORK] - GNU parallel's --sshlogin, for real: starts sshd on 127.0.0.1 (a fresh
# host key and login key in a temporary folder, a free port, as this script's child), renders
# scenes/lake.yaml (12 frames at 160x90 with its sound track) in 4 slices through
# `scripts/farm/parallel.sh DIR JOBS -S "2/ssh -p PORT ... root@127.0.0.1"`, joins, and holds
# frames and audio.wav to one process byte for byte. `make farm-test` runs it after the Slurm
# check. The sshd it started is stopped on the way out.
#
# Environment: WW_BIN. Exit: 0 same bytes, 1 a difference or a failed job, 77 skipped (not root,
# no sshd, or sshd does not start here: the reason is shown).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
SKIP=77
skip() { echo "farm-test (ssh): SKIPPED: $*" >&2; exit "$SKIP"; }
say() { echo "farm-test (ssh): $*"; }

[ "$(id -u)" -eq 0 ] || skip "sshd is started as root, and this is uid $(id -u)"
for t in /usr/sbin/sshd ssh ssh-keygen parallel; do
    command -v "$t" >/dev/null 2>&1 || skip "$t is not installed (sh scripts/install-deps.sh --farm)"
done
ww=$(farm_ww)
T=$(mktemp -d /tmp/ww-ssh.XXXXXX)
chmod 700 "$T"
pid=""
stop() {
    rc=$?
    trap - EXIT
    if [ -n "$pid" ]; then kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; say "stopped sshd"; fi
    rm -rf "$T"
    exit "$rc"
}
trap stop EXIT
trap 'exit 130' INT TERM

ssh-keygen -q -t ed25519 -N '' -f "$T/host"
ssh-keygen -q -t ed25519 -N '' -f "$T/login"
cp "$T/login.pub" "$T/authorized_keys"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
cat >"$T/sshd_config" <<CONF
Port $port
ListenAddress 127.0.0.1
HostKey $T/host
AuthorizedKeysFile $T/authorized_keys
PermitRootLogin prohibit-password
PasswordAuthentication no
KbdInteractiveAuthentication no
UsePAM no
StrictModes no
PidFile none
CONF
mkdir -p /run/sshd # sshd's privilege separation folder (the package's service makes it)
/usr/sbin/sshd -D -f "$T/sshd_config" -E "$T/sshd.log" &
pid=$!
sshcmd="ssh -p $port -i $T/login -o StrictHostKeyChecking=no -o UserKnownHostsFile=/dev/null -o LogLevel=error -o BatchMode=yes"
i=0
until $sshcmd root@127.0.0.1 true 2>"$T/ssh.err"; do
    i=$((i + 1))
    kill -0 "$pid" 2>/dev/null && [ "$i" -le 10 ] ||
        skip "no ssh login to sshd on 127.0.0.1:$port: $(cat "$T/ssh.err") $(tail -n 3 "$T/sshd.log")"
    sleep 1
done
say "sshd up on 127.0.0.1:$port, login as root with a fresh key"

work=${1:-$T/work}
mkdir -p "$work/one"
work=$(cd "$work" && pwd)
scene=$(pwd)/scenes/lake.yaml
export LP_NUM_THREADS=1
"$ww" render "$scene" --size 160x90 --frames 0:12 -o "$work/one" --audio "$work/one/$FARM_AUDIO" --quiet
farm_render_jobs "$work/par" 4 "$scene" --size 160x90 --frames 0:12 --quiet >"$work/jobs"
sh "$here/parallel.sh" "$work/par" "$work/jobs" -S "2/$sshcmd root@127.0.0.1" 2>"$T/join.err" ||
    { cat "$T/join.err" >&2; exit 1; }
# every line ran through the ssh login, none on this machine directly (":" in the joblog)
ran=$(awk -F'\t' 'NR > 1 && $2 ~ /^ssh / && $7 == 0' "$work/par/parallel.joblog" | wc -l)
say "$ran of 4 slices ran over ssh (parallel's joblog: host and exit status)"
[ "$ran" -eq 4 ] || { cat "$work/par/parallel.joblog" >&2; exit 1; }
farm_same_render "$work/one" "$work/par"
say "PASSED: the slices rendered over ssh and joined are one process's bytes"
