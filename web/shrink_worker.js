// The page's shrinker (viewer/shrink_worker.h, docs/WEB.md): the --pre-js of shrink-worker.js,
// the flood CLI built once more for a Web Worker (cmake/web.cmake). The page posts
//   {name, bytes, args, crashAt}
// and the worker runs `flood shrink /in/NAME -o /out/repro.geojson ARGS` on those bytes,
// posting back
//   {progress: [tries, vertices]}  the CLI's progress line (at most five a second)
//   {line: text}                   each line the CLI says on stderr (or stdout)
//   {done: exitCode, repro}        the repro file's bytes, null when none was written.
// Nothing here catches a trap or an abort: it ends this worker, and the page hears of it as
// the worker's error event. crashAt > 0 (the page's test-only URL parameter
// test-shrink-crash=N) aborts at the CLI's Nth clock reading, about its Nth try; slowMs > 0
// (test-shrink-slow=MS) makes each reading MS longer.
Module["print"] = (text) => postMessage({ line: text });
Module["printErr"] = (text) => {
  const line = text.replace(/\x1b\[K/g, "");
  const m = /^shrink: (\d+) tries, (\d+) vertices/.exec(line);
  if (m) postMessage({ progress: [Number(m[1]), Number(m[2])] });
  else if (line) postMessage({ line });
};
Module["preRun"] = (Module["preRun"] || []).concat(() => {
  // The CLI rewrites its progress line with "\r" (stderr is a terminal here, as it is one in
  // a shell): each rewrite is a line of its own.
  const put = TTY.default_tty1_ops.put_char;
  TTY.default_tty1_ops.put_char = (tty, val) => put(tty, val === 13 ? 10 : val);
});
let floodJob = null;
const floodRun = () => {
  if (!floodJob || !runtimeInitialized) return;
  // No destructuring: Emscripten 3.1.6's JS optimizer drops such a declaration.
  const job = floodJob, name = job.name, crashAt = job.crashAt, slowMs = job.slowMs || 0;
  floodJob = null;
  FS.mkdirTree("/in");
  FS.mkdirTree("/out");
  FS.writeFile("/in/" + name, job.bytes);
  if (crashAt > 0 || slowMs > 0) {
    let readings = 0;
    const now = _emscripten_get_now;
    _emscripten_get_now = () => {
      if (++readings === crashAt) abort("a forced crash (test-shrink-crash=" + crashAt + ")");
      // test-shrink-slow=MS: each reading (about a try) takes MS longer, so that a test sees
      // the page draw while this worker works, however fast the machine.
      for (const until = now() + slowMs; now() < until;) {}
      return now();
    };
  }
  const code = callMain(["shrink", "/in/" + name, "-o", "/out/repro.geojson"].concat(job.args));
  let repro = null;
  try {
    repro = FS.readFile("/out/repro.geojson");
  } catch (e) {}
  postMessage({ done: code, repro });
};
// Run from a task of its own, not from inside the runtime's start-up promise: an error thrown
// there would be an unhandled rejection, which the page never hears of.
Module["onRuntimeInitialized"] = () => setTimeout(floodRun, 0);
onmessage = (e) => {
  floodJob = e.data;
  setTimeout(floodRun, 0);
};
