// The JavaScript peers of the benchmark (issue 13), timed in-process under Node.js on the
// inputs `flood-bench dump` wrote: earcut (the anchor without any binding's call overhead),
// libtess (the GLU tessellator ported to JavaScript) and poly2tri (constrained Delaunay).
//
//   node peers_time.mjs DIR PEER [--timeout S]    every input of DIR/manifest.tsv -> DIR/PEER-node.tsv
//   node peers_time.mjs --one PEER FILE.poly OUT.tri                  one input, one JSON line
//
// Each input runs in its own Node process with a time limit, so a peer that throws, hangs or
// runs out of memory costs one row; families stop at the size that timed out or whose time,
// predicted from the two smaller sizes, is over the limit (the C++ driver's policy). The
// triangles go to DIR/<name>.PEER-node.tri as uint32 triples of input vertex indices, which
// `flood-bench run` judges with Flood's exact checker like every other peer's.
// The node_modules come from EARCUT_DIR (scripts/bench.sh runs `npm ci` there) or beside this file.
import { spawnSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const require = createRequire(process.env.EARCUT_DIR ? resolve(process.env.EARCUT_DIR) + '/' : import.meta.url);
// earcut 3 is an ES module, libtess and poly2tri CommonJS: import() loads either.
const load = async name => {
    const m = await import(pathToFileURL(require.resolve(name)).href);
    return m.default ?? m;
};

// Binary .poly (bench/inputs.h): magic, ring count, (count, outer) per ring, x y float64 pairs.
function readPoly(path) {
    const b = readFileSync(path);
    if (b.toString('latin1', 0, 8) !== 'FLPOLY2\n') throw new Error('not a .poly file: ' + path);
    const rings = Number(b.readBigUInt64LE(8));
    const shape = [];
    let total = 0;
    for (let r = 0; r < rings; ++r) {
        const count = Number(b.readBigUInt64LE(16 + 16 * r));
        shape.push({ first: total, count, outer: b.readBigUInt64LE(24 + 16 * r) !== 0n });
        total += count;
    }
    const start = 16 + 16 * rings;
    const xy = new Float64Array(2 * total);
    for (let i = 0; i < 2 * total; ++i) xy[i] = b.readDoubleLE(start + 8 * i);
    const parts = [];  // per part: its rings, outer first
    for (const ring of shape) {
        if (ring.outer) parts.push([]);
        parts[parts.length - 1].push(ring);
    }
    return { xy, parts };
}

// Each peer: prepare(poly) -> state reused between runs (what a caller would already hold),
// run(state) -> { tris: flat input indices, added: triangles with a vertex that is not an input point }.
const peers = {
    earcut: async () => {
        const earcut = await load('earcut');
        return {
            prepare: ({ xy, parts }) => parts.map(rings => {
                const first = rings[0].first, last = rings[rings.length - 1].first + rings[rings.length - 1].count;
                return { first, coords: xy.subarray(2 * first, 2 * last), holes: rings.slice(1).map(r => r.first - first) };
            }),
            run: state => {
                const tris = [];
                for (const { first, coords, holes } of state)
                    for (const v of earcut(coords, holes)) tris.push(v + first);
                return { tris, added: 0 };
            },
        };
    },
    libtess: async () => {
        const libtess = await load('libtess');
        return {
            prepare: poly => poly,
            run: ({ xy, parts }) => {
                const tris = [];
                let added = 0, pending = [], error = null;
                const tess = new libtess.GluTesselator();
                tess.gluTessCallback(libtess.gluEnum.GLU_TESS_EDGE_FLAG, () => {});  // triangles only
                tess.gluTessCallback(libtess.gluEnum.GLU_TESS_VERTEX_DATA, id => {
                    pending.push(id);
                    if (pending.length === 3) {
                        if (pending.some(v => v < 0)) ++added;
                        else tris.push(...pending);
                        pending = [];
                    }
                });
                tess.gluTessCallback(libtess.gluEnum.GLU_TESS_COMBINE, () => -1);  // a new point
                tess.gluTessCallback(libtess.gluEnum.GLU_TESS_ERROR, e => { error ??= 'libtess error ' + e; });
                tess.gluTessProperty(libtess.gluEnum.GLU_TESS_WINDING_RULE, libtess.windingRule.GLU_TESS_WINDING_ODD);
                tess.gluTessNormal(0, 0, 1);
                tess.gluTessBeginPolygon(null);
                for (const rings of parts)
                    for (const r of rings) {
                        tess.gluTessBeginContour();
                        for (let v = r.first; v < r.first + r.count; ++v)
                            tess.gluTessVertex([xy[2 * v], xy[2 * v + 1], 0], v);
                        tess.gluTessEndContour();
                    }
                tess.gluTessEndPolygon();
                if (error) throw new Error(error);
                return { tris, added };
            },
        };
    },
    poly2tri: async () => {
        const poly2tri = await load('poly2tri');
        const ring = (xy, r) => {
            const pts = [];
            for (let v = r.first; v < r.first + r.count; ++v) pts.push({ x: xy[2 * v], y: xy[2 * v + 1], id: v });
            return pts;
        };
        return {
            prepare: poly => poly,
            run: ({ xy, parts }) => {
                const tris = [];
                for (const rings of parts) {
                    // poly2tri keeps its sweep state on the points: fresh ones every run.
                    const ctx = new poly2tri.SweepContext(ring(xy, rings[0]));
                    for (const h of rings.slice(1)) ctx.addHole(ring(xy, h));
                    ctx.triangulate();
                    for (const t of ctx.getTriangles())
                        for (let k = 0; k < 3; ++k) tris.push(t.getPoint(k).id);
                }
                return { tris, added: 0 };
            },
        };
    },
};

// The C++ driver's policy, after a JIT warm-up of ~0.2 s: the median of >= 3 runs until ~0.5 s
// are spent (at most 21); one run when a run takes over 10 s. A run under 1 ms is timed as a
// batch of calls lasting ~1 ms (per call: the batch's time / its calls), as the clock's own
// cost and resolution would otherwise dominate.
function timeRuns(f) {
    const batchOf = k => {
        const t0 = process.hrtime.bigint();
        let r;
        for (let i = 0; i < k; ++i) r = f();
        return [Number(process.hrtime.bigint() - t0) / k, r];
    };
    let [first, result] = batchOf(1);
    for (let spent = first; spent < 2e8 && first < 1e9;) spent += batchOf(1)[0];
    const calls = Math.max(1, Math.min(100000, Math.ceil(1e6 / Math.max(1, batchOf(1)[0]))));
    const t = [];
    let total = 0;
    for (;;) {
        const [ns, r] = batchOf(calls);
        t.push(ns);
        total += ns * calls;
        result = r;
        if (t[0] > 10e9) break;
        if (t.length >= 3 && (total > 0.5e9 || t.length >= 21)) break;
    }
    t.sort((a, b) => a - b);
    return { ns: t[t.length >> 1], runs: t.length * calls, result };
}

async function one(peer, path, triPath) {
    const p = await peers[peer]();
    const state = p.prepare(readPoly(path));
    const { ns, runs, result } = timeRuns(() => p.run(state));
    writeFileSync(triPath, Buffer.from(new Uint32Array(result.tris).buffer));
    return { status: 'ok', ns, runs, triangles: result.tris.length / 3, added: result.added, detail: '' };
}

function all(dir, peer, timeoutS) {
    const lines = readFileSync(dir + '/manifest.tsv', 'utf8').trimEnd().split('\n').slice(1);
    const rows = ['name\tstatus\tns\truns\ttriangles\tdetail\tadded'];
    const history = new Map(), givenUp = new Set();
    const script = fileURLToPath(import.meta.url);
    for (const line of lines) {
        const [name, family, size, vertices, , , path] = line.split('\t');
        const h = history.get(family) ?? [];
        history.set(family, h);
        let row;
        if (+size > 1e6) {  // 10^7 (a few cheap families): Flood and the floor only
            row = { status: 'skipped', detail: 'above 10^6 only Flood and the floor run' };
        } else if (family !== 'fixture' && givenUp.has(family)) {
            row = { status: 'skipped', detail: 'timed out or predicted over the limit at a smaller size' };
        } else if (family !== 'fixture' && h.length >= 2 &&
                   h[h.length - 1] * Math.max(10, h[h.length - 1] / h[h.length - 2]) * 1e-9 > 0.75 * timeoutS) {
            givenUp.add(family);
            const predicted = h[h.length - 1] * Math.max(10, h[h.length - 1] / h[h.length - 2]) * 1e-9;
            row = { status: 'skipped', detail: `predicted ${Math.floor(predicted)} s per run from the smaller sizes` };
        } else {
            const triPath = `${dir}/${name.replaceAll('/', '_')}.${peer}-node.tri`;
            const r = spawnSync(process.execPath, ['--max-old-space-size=8192', '--stack-size=65500', script, '--one', peer, path, triPath],
                                { timeout: timeoutS * 1000, encoding: 'utf8', maxBuffer: 1 << 20 });
            const out = (r.stdout ?? '').trim();
            if (r.error?.code === 'ETIMEDOUT' || r.signal === 'SIGTERM') row = { status: 'timeout', detail: `over ${timeoutS} s` };
            else if (out.startsWith('{')) row = JSON.parse(out);
            else row = { status: 'crash', detail: (r.stderr ?? '').trim().split('\n').slice(-1)[0] || `exit ${r.status} ${r.signal ?? ''}` };
            if (row.status === 'ok') h.push(row.ns);
            else if (row.status !== 'error') givenUp.add(family);
        }
        const clean = s => String(s ?? '').replace(/[\t\r\n]/g, ' ').slice(0, 160);
        rows.push([name, row.status, row.ns ?? 0, row.runs ?? 0, row.triangles ?? 0, clean(row.detail), row.added ?? 0].join('\t'));
        process.stderr.write(`${name.padEnd(30)} ${peer.padEnd(10)} ${row.status.padEnd(8)} ${((row.ns ?? 0) / Math.max(1, +vertices)).toFixed(1).padStart(12)} ns/vertex ${clean(row.detail)}\n`);
    }
    writeFileSync(`${dir}/${peer}-node.tsv`, rows.join('\n') + '\n');
}

const a = process.argv.slice(2);
if (a[0] === '--one' && a.length === 4) {
    let row;
    try {
        row = await one(a[1], a[2], a[3]);
    } catch (e) {  // the peer refused or failed: a row, like a C++ peer's error
        row = { status: 'error', ns: 0, runs: 0, triangles: 0, added: 0, detail: String(e?.message ?? e) };
    }
    console.log(JSON.stringify(row));
} else if (a.length >= 2 && peers[a[1]]) {
    const t = a.indexOf('--timeout');
    all(a[0], a[1], t >= 0 ? Number(a[t + 1]) : 60);
} else {
    console.error('usage: node peers_time.mjs DIR earcut|libtess|poly2tri [--timeout S]\n' +
                  '       node peers_time.mjs --one PEER FILE.poly OUT.tri');
    process.exit(2);
}
