#!/bin/sh
# install-deps.sh - install the Debian 12 packages waterworld builds, runs and tests with.
# Idempotent: installs only what is missing, and says nothing when everything is there.
# Needs root (or sudo) only when something is missing.
set -eu

# build: compiler, libyaml, cglm, stb, OpenEXR (C API), EGL/GL headers
# run:   EGL (glvnd + Mesa), OSMesa, llvmpipe (libgl1-mesa-dri)
# tests: the outside tools our outputs are checked with: ImageMagick (compare), OpenImageIO
#        (oiiotool, idiff), ffmpeg (ffprobe, make-video.sh), Chromium (the HTML report's picture)
PKGS="gcc make libc6-dev pkg-config libyaml-dev libcglm-dev libstb-dev libopenexr-dev
libegl-dev libgl-dev libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6 libosmesa6-dev
imagemagick openimageio-tools ffmpeg chromium"
# `make fuzz` only: clang with libFuzzer, zlib (the inflate target checks against it)
[ "${1:-}" = "--fuzz" ] && PKGS="clang libclang-rt-14-dev zlib1g-dev"

missing=""
for p in $PKGS; do
    st=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
    [ "$st" = "installed" ] || missing="$missing $p"
done
[ -z "$missing" ] && exit 0

echo "install-deps: installing:$missing" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
        echo "install-deps: need root to install:$missing" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
echo "install-deps: done" >&2
