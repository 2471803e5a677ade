#!/bin/sh
# make-golden.sh [BIN] - re-bless the golden frames in golden/ (see README, "Golden images").
# Renders the frames the tests compare and records the renderer that made them.
set -eu
BIN=${1:-./waterworld}
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
echo "golden: blessed with $(cat golden/RENDERER); review the PNGs, then commit them" >&2
