#!/bin/sh
# install-pixelmatch.sh - what the tests compare_pixelmatch_agrees_* check `waterworld compare`
# against: Node.js (Debian's nodejs, the runtime alone, no npm) and Mapbox's pixelmatch 7.2.0,
# its tarball fetched from the npm registry, its SHA-512 checked against the pinned one below,
# unpacked into ${XDG_CACHE_HOME:-~/.cache}/waterworld/pixelmatch-7.2.0 (where the tests look).
# Idempotent, and silent once done. Without network, or without root to install nodejs, it says
# so and exits 0: those tests then skip, naming this script. A tarball with another hash is an
# error (exit 1) and is not unpacked.
set -eu

VERSION=7.2.0
URL=https://registry.npmjs.org/pixelmatch/-/pixelmatch-$VERSION.tgz
# the registry's dist.integrity for 7.2.0, sha512-xhcb4yHu9sM/G7foGzoLtXYcC0zHEaOXXjRKhGup0fw78Nf2
# Tkiapv4EQyMzrbcmQPsllAI7DbFY2UT7PlI9Pg==, in hex
SHA512=c6171be321eef6c33f1bb7e81b3a0bb5761c0b4cc711a3975e344a846ba9d1fc3bf0d7f64e489aa6fe04432333adb72640fb2594023b0db158d944fb3e523d3e
CACHE=${XDG_CACHE_HOME:-$HOME/.cache}/waterworld
DEST=$CACHE/pixelmatch-$VERSION

say() { echo "install-pixelmatch: $*" >&2; }

# Node.js: Debian's runtime with the CA certificates (for the download below), no recommends
if ! command -v node >/dev/null 2>&1; then
    SUDO=""
    if [ "$(id -u)" -ne 0 ]; then
        if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
            say "node is missing and installing nodejs needs root; the pixelmatch tests will skip"
            exit 0
        fi
    fi
    say "installing nodejs"
    export DEBIAN_FRONTEND=noninteractive
    if ! { $SUDO apt-get update -qq >/dev/null &&
           $SUDO apt-get install -y -qq --no-install-recommends nodejs ca-certificates >/dev/null; }; then
        say "could not install nodejs (no network?); the pixelmatch tests will skip"
        exit 0
    fi
fi

# done already: the stamp holds the hash of the tarball it was unpacked from
[ -f "$DEST/index.js" ] && [ "$(cat "$DEST/.sha512" 2>/dev/null)" = "$SHA512" ] && exit 0

mkdir -p "$CACHE"
tmp=$(mktemp -d "$CACHE/.pixelmatch.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
tgz=$tmp/pixelmatch.tgz

# curl or wget when there is one (they follow the proxy settings), else node itself, trusting
# the system's certificates as they do
fetched=0
if command -v curl >/dev/null 2>&1; then
    curl -fsSL --retry 2 -o "$tgz" "$URL" 2>/dev/null && fetched=1
elif command -v wget >/dev/null 2>&1; then
    wget -q -O "$tgz" "$URL" && fetched=1
else
    node --use-openssl-ca -e '
const [url, out] = process.argv.slice(1);
const get = (u, hops) => require("https").get(u, (r) => {
    if (r.statusCode >= 300 && r.statusCode < 400 && r.headers.location && hops > 0) {
        r.resume();
        return get(new URL(r.headers.location, u).href, hops - 1);
    }
    if (r.statusCode !== 200) { console.error("HTTP " + r.statusCode); process.exit(1); }
    r.pipe(require("fs").createWriteStream(out)).on("finish", () => process.exit(0));
}).on("error", (e) => { console.error(e.message); process.exit(1); });
get(url, 3);' "$URL" "$tgz" 2>/dev/null && fetched=1
fi
if [ "$fetched" -ne 1 ]; then
    say "could not fetch $URL (no network?); the pixelmatch tests will skip"
    exit 0
fi

got=$(sha512sum "$tgz" | cut -d' ' -f1)
if [ "$got" != "$SHA512" ]; then
    say "$URL has SHA-512 $got, not the pinned $SHA512: not unpacked"
    exit 1
fi

# npm tarballs hold one folder, package/; unpack beside the cache entry, then swap it in
mkdir "$tmp/x"
tar -xzf "$tgz" -C "$tmp/x"
echo "$SHA512" > "$tmp/x/package/.sha512"
rm -rf "$DEST"
mv "$tmp/x/package" "$DEST"
say "pixelmatch $VERSION in $DEST"
