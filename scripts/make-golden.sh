#!/bin/sh
# make-golden.sh [--check | --key | --measure] [BIN] - re-bless the golden frames in golden/ (see
# README, "Golden images"), or with --check compare fresh renders with them through
# `render --golden`, or with --measure print how far this renderer is from the flat goldens
# (per image: largest channel difference in 8-bit levels, PSNR, share of pixels differing;
# the figures tests/golden.c's GOLDEN_FOREIGN_* tolerances are chosen from).
#
# Layout: golden/minimal/frame_00000.png, golden/demo/frame_XXXXX.png and
# golden/features/NAME.png are the renders of one renderer, recorded in golden/RENDERER
# ("GL_RENDERER | GL_VERSION") and golden/KEY (its renderer key, `waterworld backends --key`).
# --key blesses this machine's renderer beside them instead, into golden/minimal/KEY/,
# golden/demo/KEY/ and golden/features/KEY/ (with KEY/RENDERER), leaving the flat ones alone.
# `render --golden golden/demo` and the tests look in the KEY/ folder of the renderer they run on
# first, then take the flat frame.
set -eu
check=0
per_key=0
measure=0
case "${1:-}" in
--check) check=1; shift ;;
--key) per_key=1; shift ;;
--measure) measure=1; shift ;;
esac
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

if [ "$measure" = 1 ]; then
    # the same renders as blessing, into a temporary folder, each compared with its flat golden
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    "$BIN" render scenes/minimal.yaml --frames 1 -o "$tmp/minimal" --quiet
    "$BIN" render scenes/demo.yaml --size 256x144 --frames 1 -o "$tmp/demo" --quiet
    "$BIN" render scenes/demo.yaml --size 256x144 --frames 150:151 -o "$tmp/demo" --quiet
    pairs="golden/minimal/frame_00000.png:$tmp/minimal/frame_00000.png
golden/demo/frame_00000.png:$tmp/demo/frame_00000.png
golden/demo/frame_00150.png:$tmp/demo/frame_00150.png"
    for s in scenes/features/*.yaml; do
        n=$(basename "$s" .yaml)
        "$BIN" render "$s" --frames 1 -o "$tmp/features/$n" --quiet
        pairs="$pairs
golden/features/$n.png:$tmp/features/$n/frame_00000.png"
    done
    echo "renderer $("$BIN" backends --renderer) (key $("$BIN" backends --key)) against the goldens of $(cat golden/KEY)"
    printf '%-30s %10s %8s %11s\n' image max_levels psnr_db differ_%
    echo "$pairs" | while IFS=: read -r g a; do
        j=$("$BIN" compare "$g" "$a" --json 2>/dev/null || true)
        field() { echo "$j" | sed -n "s/.*\"$1\":\([^,}]*\).*/\1/p"; }
        echo "${g#golden/} $(field max_abs) $(field psnr) $(field diff_percent)"
    done | awk '{ psnr = $3 == "null" ? "inf" : sprintf("%.1f", $3)
                  printf "%-30s %10.0f %8s %11.4f\n", $1, $2, psnr, $4 }' 
    exit 0
fi

key=$("$BIN" backends --key)
sub=
[ "$per_key" = 1 ] && sub=/$key
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$BIN" render scenes/minimal.yaml --frames 1 -o "$tmp/minimal" --quiet
"$BIN" render scenes/demo.yaml --size 256x144 --frames 1 -o "$tmp/demo" --quiet
"$BIN" render scenes/demo.yaml --size 256x144 --frames 150:151 -o "$tmp/demo" --quiet
mkdir -p "golden/minimal$sub" "golden/demo$sub"
cp "$tmp/minimal/frame_00000.png" "golden/minimal$sub/"
cp "$tmp/demo/frame_00000.png" "$tmp/demo/frame_00150.png" "golden/demo$sub/"
# one golden per feature of the render pipeline: frame 0 of each scenes/features/NAME.yaml
mkdir -p "golden/features$sub"
for s in scenes/features/*.yaml; do
    [ -e "$s" ] || continue
    n=$(basename "$s" .yaml)
    "$BIN" render "$s" --frames 1 -o "$tmp/features/$n" --quiet
    cp "$tmp/features/$n/frame_00000.png" "golden/features$sub/$n.png"
done
if [ "$per_key" = 1 ]; then
    "$BIN" backends --renderer > "golden/features/$key/RENDERER"
    echo "golden: blessed $key ($(cat "golden/features/$key/RENDERER")) into golden/*/$key/; review the PNGs, then commit them" >&2
    exit 0
fi
"$BIN" backends --renderer > golden/RENDERER
echo "$key" > golden/KEY
echo "golden: blessed with $(cat golden/RENDERER) (key $key); review the PNGs, then commit them" >&2
