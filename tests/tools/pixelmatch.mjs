// pixelmatch.mjs - the reference side of the test compare_pixelmatch_agrees (tests/test_compare.c):
// runs Mapbox's pixelmatch on raw RGBA pairs that the C test wrote, so no PNG reader is involved.
//
//   node tests/tools/pixelmatch.mjs PIXELMATCH_DIR WIDTH HEIGHT THRESHOLD A.rgba B.rgba OUT.rgba [A B OUT]...
//   node tests/tools/pixelmatch.mjs PIXELMATCH_DIR WIDTH HEIGHT THRESHOLD @LIST
//
// (LIST: a file of such triples, one a line, the three paths separated by tabs.)
// PIXELMATCH_DIR is an unpacked pixelmatch package (scripts/install-pixelmatch.sh puts 7.2.0 in
// ~/.cache/waterworld/pixelmatch-7.2.0). Each .rgba file is WIDTH x HEIGHT x 4 bytes, top row
// first. For each pair one JSON line goes to stdout:
//   {"version":"7.2.0","diff":N,"aa":M}
// diff: pixelmatch's count with includeAA false (anti-aliasing not counted); aa: the pixels over
// the threshold that it calls anti-aliasing (its count with includeAA true, less diff). OUT.rgba
// gets its diff image: anti-aliasing yellow (255,255,0), differences red (255,0,0), the rest grey
// (written into a Uint8ClampedArray, as a canvas's ImageData is: grey values are rounded).
// Semi-transparent pixels are blended on white (checkerboard false), as waterworld compare blends.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [dir, w, h, t, ...args] = process.argv.slice(2);
const files = args.length === 1 && args[0].startsWith('@')
    ? readFileSync(args[0].slice(1), 'utf8').split('\n').filter((l) => l).flatMap((l) => l.split('\t'))
    : args;
if (!dir || files.length === 0 || files.length % 3 !== 0) {
    console.error('usage: pixelmatch.mjs PIXELMATCH_DIR WIDTH HEIGHT THRESHOLD (A.rgba B.rgba OUT.rgba)... | @LIST');
    process.exit(2);
}
const version = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8')).version;
const pixelmatch = (await import(pathToFileURL(join(dir, 'index.js')).href)).default;
const width = Number(w), height = Number(h);
const common = {
    threshold: Number(t), alpha: 0.1, aaColor: [255, 255, 0], diffColor: [255, 0, 0],
    checkerboard: false,
};

for (let k = 0; k < files.length; k += 3) {
    const a = readFileSync(files[k]), b = readFileSync(files[k + 1]);
    const out = new Uint8ClampedArray(a.length);
    const diff = pixelmatch(a, b, out, width, height, { ...common, includeAA: false });
    const all = pixelmatch(a, b, null, width, height, { ...common, includeAA: true });
    writeFileSync(files[k + 2], out);
    console.log(JSON.stringify({ version, diff, aa: all - diff }));
}
