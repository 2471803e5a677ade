#!/bin/sh
# make-golden.sh [--check] [BIN] - re-bless the golden frames in golden/ (see README, "Golden
# images"), or with --check compare fresh renders with them through `render --golden`.
#
# Layout: flat. golden/minimal/frame_00000.png, golden/demo/frame_XXXXX.png and
# golden/features/NAME.png are the renders of one renderer, recorded in golden/RENDERER
# ("GL_RENDERER | GL_VERSION") and golden/KEY (its renderer key, `waterworld backends --key`).
# `render --golden golden/demo` looks in golden/demo/KEY/ first and finds nothing there, then
# takes the flat frame; per-renderer folders (golden/demo/nvidia-535/...) may be added beside.
set -eu
check=0
if [ "${1:-}" = "--check" ]; then
    check=1
    shift
fi
BIN=${1:-./waterworld}

if [ "$check" = 1 ]; then
    # exit 1 when a frame differs; out/golden-check/*/report.html says where
    rc=0
    "$BIN" render scenes/minimal.yaml --frames 1 -o out/golden-check/minimal --golden golden/minimal --quiet || rc=$?
    "$BIN" render scenes/demo.yaml --size 256x144 --frames 1 -o out/golden-check/demo --golden golden/demo --quiet || rc=$?
    "$BIN" render scenes/demo.yaml --size 256x144 --frames 150:151 -o out/golden-check/demo150 --golden golden/demo --quiet || rc=$?
    echo "golden check: $( [ $rc = 0 ] && echo passed || echo FAILED): reports in out/golden-check/*/report.html (renderer key $("$BIN" backends --key), goldens blessed on $(cat golden/KEY 2>/dev/null || echo '?'))" >&2
    exit $rc
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$BIN" render scenes/minimal.yaml --frames 1 -o "$tmp/minimal" --quiet
"$BIN" render scenes/demo.yaml --size 256x144 --frames 1 -o "$tmp/demo" --quiet
"$BIN" render scenes/demo.yaml --size 256x144 --frames 150:151 -o "$tmp/demo" --quiet
mkdir -p golden/minimal golden/demo
cp "$tmp/minimal/frame_00000.png" golden/minimal/
cp "$tmp/demo/frame_00000.png" "$tmp/demo/frame_00150.png" golden/demo/
# one golden per feature of the render pipeline: frame 0 of each scenes/features/NAME.yaml
mkdir -p golden/features
for s in scenes/features/*.yaml; do
    [ -e "$s" ] || continue
    n=$(basename "$s" .yaml)
    "$BIN" render "$s" --frames 1 -o "$tmp/features/$n" --quiet
    cp "$tmp/features/$n/frame_00000.png" "golden/features/$n.png"
done
"$BIN" backends --renderer > golden/RENDERER
"$BIN" backends --key > golden/KEY
echo "golden: blessed with $(cat golden/RENDERER) (key $(cat golden/KEY)); review the PNGs, then commit them" >&2
