#!/bin/sh
# install-deps.sh [--fuzz|--farm] - install the Debian packages waterworld builds, runs and tests with,
# on Debian 12 (bookworm), 13 (trixie) and unstable (sid).
# Idempotent: installs only what is missing, and says nothing when everything is there.
# Needs root (or sudo) only when something is missing.
set -eu

# build: compiler, libyaml, cglm, stb, OpenEXR (C API), EGL/GL headers; zlib for the test that
#        replays the fuzz seeds (the inflate target checks our inflate against it)
# run:   EGL (glvnd + Mesa), llvmpipe (libgl1-mesa-dri)
# tests: the outside tools our outputs are checked with: ImageMagick (compare), OpenImageIO
#        (oiiotool, idiff), ffmpeg (ffprobe, make-video.sh), Chromium (the HTML report's picture),
#        and pixelmatch under Node.js (below); GNU parallel (the farm's job lines, run and joined)
PKGS="gcc make libc6-dev pkg-config libyaml-dev libcglm-dev libstb-dev libopenexr-dev zlib1g-dev
libegl-dev libgl-dev libegl1 libegl-mesa0 libgl1-mesa-dri
imagemagick openimageio-tools ffmpeg chromium parallel"
# optional, where the release has it: OSMesa, the second backend (Mesa 25.1 removed it, so
# Debian 12 and 13 have it and unstable does not); without it EGL alone runs and the tests
# that need OSMesa are skipped with the reason
OPTIONAL="libosmesa6"

# is a package installed?
installed() {
    [ "$(dpkg-query -W -f='${db:Status-Status}' "$1" 2>/dev/null || true)" = "installed" ]
}
# does the release have it (a candidate in apt's lists)?
available() {
    apt-cache policy "$1" 2>/dev/null | grep -q 'Candidate: [^(]'
}
# the candidate's upstream major version: 1:19.0-63 -> 19
candidate_major() {
    apt-cache policy "$1" 2>/dev/null | sed -n 's/^ *Candidate: \([0-9]*:\)\{0,1\}\([0-9]*\).*/\2/p'
}

# `make fuzz` only: clang with libFuzzer, whose runtime package carries clang's major version
# (14 on Debian 12, 19 on 13, 21 on unstable in 2026)
fuzz=0
[ "${1:-}" = "--fuzz" ] && fuzz=1
fuzz_pkgs() {
    v=""
    if command -v clang >/dev/null 2>&1; then
        v=$(clang --version | sed -n 's/.*clang version \([0-9]*\).*/\1/p' | head -n 1)
    fi
    [ -n "$v" ] || v=$(candidate_major clang)
    echo "clang${v:+ libclang-rt-$v-dev} zlib1g-dev"
}
if [ "$fuzz" = 1 ]; then PKGS=$(fuzz_pkgs); OPTIONAL=""; fi

# `make farm-test` only: a one-node Slurm cluster and an sshd on this machine
# (scripts/farm/check-slurm.sh, check-ssh.sh start the daemons themselves, on 127.0.0.1; on a
# machine with systemd the packages also enable their own services)
farm=0
[ "${1:-}" = "--farm" ] && farm=1
if [ "$farm" = 1 ]; then PKGS="slurmctld slurmd slurm-client munge parallel openssh-server"; OPTIONAL=""; fi

missing=""
for p in $PKGS; do installed "$p" || missing="$missing $p"; done
# optional packages: asked for only when the lists say the release has them
optional=""
for p in $OPTIONAL; do installed "$p" || optional="$optional $p"; done
want_optional() {
    rest=""
    for p in $optional; do
        if available "$p"; then missing="$missing $p"; else rest="$rest $p"; fi
    done
    optional=$rest
}
want_optional

# the reference the compare tests check against: Node.js and pixelmatch 7.2.0 from the npm
# registry, hash-pinned (scripts/install-pixelmatch.sh; quiet when there, a skip without network)
pixelmatch() { [ "$fuzz" = 1 ] || [ "$farm" = 1 ] || sh "$(dirname "$0")/install-pixelmatch.sh"; }
[ -z "$missing" ] && { pixelmatch; exit 0; }

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
        echo "install-deps: need root to install:$missing" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null
# the fresh lists may know the optional packages, and the fuzz runtime's version
want_optional
[ "$fuzz" = 1 ] && missing=" $(fuzz_pkgs)"
echo "install-deps: installing:$missing" >&2
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
echo "install-deps: done" >&2
pixelmatch
