// earcut under Node.js, timed in-process: the anchor of the small-polygon benchmark
// (docs/BENCHMARKS.md, issue 13). Usage: node earcut_time.mjs FIXTURE.json...
// Each fixture (a JSON array of rings) is cleaned as Flood's reader cleans it (repeated
// consecutive points and the closing point dropped), so both triangulate the same vertices.
// Per fixture: the least of 15 batch means, each batch ~20 ms after a warm-up, as
// flood-small-bench does. Prints TSV: file, vertices, ns per call, triangles.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { pathToFileURL } from 'node:url';

// earcut is installed beside this script or in EARCUT_DIR (scripts/bench.sh installs it there).
const where = process.env.EARCUT_DIR ? process.env.EARCUT_DIR + '/' : import.meta.url;
const require = createRequire(where);
const earcut = (await import(pathToFileURL(require.resolve('earcut')).href)).default;

function flatten(rings) {
    const coords = [], holes = [];
    for (const ring of rings) {
        const pts = [];
        for (const p of ring)
            if (!pts.length || p[0] !== pts[pts.length - 1][0] || p[1] !== pts[pts.length - 1][1]) pts.push(p);
        if (pts.length >= 2 && pts[0][0] === pts[pts.length - 1][0] && pts[0][1] === pts[pts.length - 1][1]) pts.pop();
        if (coords.length) holes.push(coords.length / 2);
        for (const p of pts) coords.push(p[0], p[1]);
    }
    return { coords, holes };
}

function nsPerCall(f) {
    let sink = 0, batch = 1;
    for (;; batch *= 2) {
        const t0 = process.hrtime.bigint();
        for (let i = 0; i < batch; ++i) sink += f();
        if (process.hrtime.bigint() - t0 > 20_000_000n) break;
    }
    let best = Infinity;
    for (let round = 0; round < 15; ++round) {
        const t0 = process.hrtime.bigint();
        for (let i = 0; i < batch; ++i) sink += f();
        best = Math.min(best, Number(process.hrtime.bigint() - t0) / batch);
    }
    if (sink === 0) console.error('no triangles');
    return best;
}

console.log('file\tvertices\tearcut_ns\ttriangles');
for (const file of process.argv.slice(2)) {
    const { coords, holes } = flatten(JSON.parse(readFileSync(file, 'utf8')));
    const triangles = earcut(coords, holes).length / 3;
    const ns = nsPerCall(() => earcut(coords, holes).length);
    console.log(`${file}\t${coords.length / 2}\t${ns.toFixed(1)}\t${triangles}`);
}
