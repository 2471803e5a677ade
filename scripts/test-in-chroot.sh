#!/bin/sh
# test-in-chroot.sh [--fresh] [--demo-only] [--root] RELEASE - try the two commands on another
# Debian release as a new user would: make (or reuse) a debootstrap chroot of RELEASE (bookworm,
# trixie or sid), copy a clean `git clone` of this repository's HEAD into the home of a user
# with sudo, run `make demo` and `make test` there as that user, and print what happened: install, build, `waterworld backends`, how far its
# renders are from the goldens, demo, the test summaries with failures and skips, the Mesa and
# GCC versions.
#
#   sudo sh scripts/test-in-chroot.sh trixie       # chroot in $WW_CHROOTS/trixie (/work/chroots)
#   --fresh       make the chroot anew (a machine that has only make), instead of reusing it
#   --demo-only   `make demo` but not `make test` (minutes instead of most of an hour)
#   --root        run them as root instead of the user "ww" (who has sudo, as the README asks)
#
# Needs root and debootstrap (installed when missing). The chroot gets /proc, /sys and /dev
# (bound), unmounted again on exit. Logs: $WW_CHROOTS/RELEASE-logs/. The archive is the one apt
# uses here (the first Debian URI in /etc/apt/sources*), or $WW_MIRROR. Exit: 0 when demo and
# test passed, 1 when one failed, 2 for bad usage or a chroot that could not be made.
set -eu

fresh=0
demo_only=0
as_root=0
while [ $# -gt 0 ]; do
    case "$1" in
    --fresh) fresh=1 ;;
    --demo-only) demo_only=1 ;;
    --root) as_root=1 ;;
    -h | --help) sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "test-in-chroot: unknown option $1" >&2; exit 2 ;;
    *) break ;;
    esac
    shift
done
release=${1:-}
case "$release" in
bookworm | trixie | sid) ;;
*) echo "usage: test-in-chroot.sh [--fresh] [--demo-only] [--root] bookworm|trixie|sid" >&2; exit 2 ;;
esac
[ "$(id -u)" -eq 0 ] || { echo "test-in-chroot: needs root (debootstrap, chroot, mount)" >&2; exit 2; }

repo=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)
head=$(git -C "$repo" rev-parse HEAD)
chroots=${WW_CHROOTS:-/work/chroots}
root=$chroots/$release
logs=$chroots/$release-logs
mkdir -p "$chroots" "$logs"

say() { printf '%s\n' "$*"; }
[ -z "$(git -C "$repo" status --porcelain --untracked-files=no)" ] ||
    say "note: uncommitted changes are not tested (the clone is of HEAD $head)"

# the Debian archive apt uses on this machine (security and updates suites aside)
mirror=${WW_MIRROR:-}
if [ -z "$mirror" ]; then
    mirror=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources 2>/dev/null |
        grep -o 'https\{0,1\}://[^ ]*/debian/\{0,1\}\( \|$\)' | grep -v security | head -n 1 | tr -d ' ')
fi
mirror=${mirror:-http://deb.debian.org/debian}

# the chroot: made once (minbase plus make and sudo, what a new user has), then reused
# never delete through a mount left by a killed run (its /dev is the host's)
if grep -q " $root/" /proc/mounts; then
    say "test-in-chroot: $root still has mounts (a run in progress, or one killed): see" \
        "grep $root /proc/mounts; umount -R them first" >&2
    exit 2
fi
if [ "$fresh" = 1 ] && [ -d "$root" ]; then
    say "chroot: removing $root (--fresh)"
    rm -rf "$root"
fi
if [ ! -e "$root/.waterworld-chroot" ]; then
    command -v debootstrap >/dev/null 2>&1 ||
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
    rm -rf "$root.tmp"
    say "chroot: debootstrap $release from $mirror into $root (a few minutes)"
    if ! debootstrap --variant=minbase --include=make,ca-certificates,sudo "$release" "$root.tmp" \
        "$mirror" >"$logs/debootstrap.log" 2>&1; then
        say "chroot: debootstrap failed; see $logs/debootstrap.log"
        tail -n 5 "$logs/debootstrap.log"
        exit 2
    fi
    # unstable's Release file may be past its Valid-Until on a mirror snapshot
    echo 'Acquire::Check-Valid-Until "false";' >"$root.tmp/etc/apt/apt.conf.d/99waterworld"
    touch "$root.tmp/.waterworld-chroot"
    mv "$root.tmp" "$root"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
# the host's own certificate authorities (a proxy's, where the registries are reached through
# one) are trusted in the chroot as on the host, so downloads behave as they do here
if ls /usr/local/share/ca-certificates/*.crt >/dev/null 2>&1; then
    mkdir -p "$root/usr/local/share/ca-certificates"
    cp /usr/local/share/ca-certificates/*.crt "$root/usr/local/share/ca-certificates/"
    chroot "$root" update-ca-certificates >/dev/null 2>&1 || true
fi

# mounts, undone on any exit; /dev is a recursive bind made a slave, so that unmounting it here
# never reaches the host's /dev
mounted=""
cleanup() {
    for m in $mounted; do umount -R -l "$m" 2>/dev/null || true; done
}
trap cleanup EXIT
trap 'exit 130' INT TERM
mnt() { # mnt TARGET ARGS...: mount unless already mounted, remember for cleanup
    t=$1
    shift
    mountpoint -q "$t" && return 0
    mount "$@" "$t"
    mounted="$t $mounted"
}
mnt "$root/proc" -t proc proc
mnt "$root/sys" -t sysfs -o ro sysfs
mnt "$root/dev" --rbind /dev
mount --make-rslave "$root/dev"

# the new user, ww, who may use sudo without a password (the installs ask for root)
if ! chroot "$root" id -u ww >/dev/null 2>&1; then
    chroot "$root" sh -c 'command -v sudo >/dev/null || { apt-get update -qq &&
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq sudo; } &&
        useradd -m -s /bin/sh ww && echo "ww ALL=(ALL) NOPASSWD: ALL" >/etc/sudoers.d/ww &&
        chmod 440 /etc/sudoers.d/ww' >"$logs/user.log" 2>&1 ||
        { say "chroot: could not add the user ww; see $logs/user.log"; exit 2; }
fi
if [ "$as_root" = 1 ]; then home=/root; spec=0:0; else
    home=/home/ww
    spec=$(chroot "$root" id -u ww):$(chroot "$root" id -g ww)
fi

# a clean clone of HEAD, where a new user would put it
rm -rf "$root$home/waterworld"
git clone -q --no-checkout "$repo" "$root$home/waterworld"
git -C "$root$home/waterworld" checkout -q --detach "$head"
chown -R "$spec" "$root$home/waterworld"

inside() { # run a shell command in the chroot as the user in the clone, with a plain environment
    chroot --userspec="$spec" "$root" /usr/bin/env -i HOME="$home" LANG=C.UTF-8 TERM=dumb \
        PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        sh -c "cd $home/waterworld && $1"
}

say "== $release ($(inside 'cat /etc/debian_version'), chroot $root, user $(inside 'id -un'), commit $(git -C "$repo" rev-parse --short HEAD))"
t0=$(date +%s)
if inside 'sh scripts/install-deps.sh' >"$logs/install.log" 2>&1; then
    what=$(sed -n 's/^install-deps: installing://p' "$logs/install.log")
    say "install: ok ($(($(date +%s) - t0)) s; ${what:+installed$what}${what:+}$([ -n "$what" ] || echo "nothing was missing"))"
    again=$(inside 'sh scripts/install-deps.sh' 2>&1 || echo "exit $?")
    say "install: run again: ${again:-quiet, nothing to do}"
else
    say "install: FAILED; $logs/install.log:"
    tail -n 10 "$logs/install.log"
    exit 1
fi
say "gcc: $(inside 'gcc --version | head -n 1')"
say "mesa: $(inside "dpkg-query -W -f='\${Version}' libgl1-mesa-dri") (libgl1-mesa-dri);" \
    "osmesa: $(inside "dpkg-query -W -f='\${Version}' libosmesa6 2>/dev/null || echo 'not installed'")"
say "openexr: $(inside "pkg-config --modversion OpenEXR"); imagemagick:" \
    "$(inside "dpkg-query -W -f='\${Version}' imagemagick")"

t0=$(date +%s)
if inside 'nice make -j"$(nproc)"' >"$logs/build.log" 2>&1; then
    say "build: ok ($(($(date +%s) - t0)) s, $(grep -c '^  CC' "$logs/build.log") files, warnings are errors)"
else
    say "build: FAILED; $logs/build.log:"
    grep -E 'error|warning' "$logs/build.log" | head -n 20
    exit 1
fi
say "backends:"
inside './waterworld backends' 2>&1 | sed 's/^/  /'
say "renderer key: $(inside './waterworld backends --key')"
# how far this Mesa is from the committed goldens (the figures the tolerances come from)
say "goldens, this renderer against golden/ (scripts/make-golden.sh --measure):"
inside 'sh scripts/make-golden.sh --measure' 2>&1 | sed 's/^/  /'

rc=0
t0=$(date +%s)
if inside 'nice make demo' >"$logs/demo.log" 2>&1; then
    say "demo: ok ($(($(date +%s) - t0)) s, $(inside 'ls out/demo | grep -c png') frames in out/demo)"
else
    rc=1
    say "demo: FAILED; $logs/demo.log:"
    tail -n 10 "$logs/demo.log"
fi
[ "$demo_only" = 1 ] && exit $rc

t0=$(date +%s)
inside 'nice make test' >"$logs/test.log" 2>&1 || rc=1
say "test: make test exit $([ $rc = 0 ] && echo 0 || echo non-zero) ($(($(date +%s) - t0)) s); full log $logs/test.log"
# make test stops when the normal suite fails: run the sanitizer suite on its own to see it too
if [ "$(grep -cE '^[0-9]+ passed, [0-9]+ failed' "$logs/test.log")" = 1 ]; then
    say "test: the normal suite failed, so make test stopped before the sanitizer suite; running make asan"
    inside 'nice make asan' >>"$logs/test.log" 2>&1 || true
fi
# the runner's closing lines (normal build, then the sanitizer build), each failed test with
# the first lines of its messages, and the skip reasons (counted over both runs)
awk '
/^[0-9]+ passed, [0-9]+ failed/ { print "  summary: " $0; grab = 0; next }
/^[A-Za-z0-9_]+ +FAIL +[0-9.]+ s$/ { print "  " $0; grab = 1; n = 0; next }
grab && /^    / { if (n++ < 8) print "  " $0; next }
{ grab = 0 }
' "$logs/test.log"
awk '/^skipped:$/ { s = 1; next } s && /^  / { print; next } { s = 0 }' "$logs/test.log" |
    sort | uniq -c | sed 's/^ */  skip x/'
exit $rc
