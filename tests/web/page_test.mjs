// The page in headless Chromium, driven over the DevTools protocol with no npm package
// (Node 20: --experimental-websocket). Run by tests/web/run.sh, which serves the site and
// makes the native screenshot and exports to compare with:
//   node --experimental-websocket page_test.mjs URL NATIVE.png CANVAS_X,Y,W,H DROP_FILE PICK_FILE OUT_DIR
//        BIG_FILE NATIVE_LAST.svg NATIVE_FRAMES_DIR
// Checks: the page loads with no console error; the URL's polygon and step are shown; the
// canvas matches the native viewer's at that step; the arrow keys step (counter and picture);
// P (Save PNG) downloads a PNG of the canvas; a file dropped on the canvas opens; Ctrl+O opens
// the browser's file picker and a file chosen there opens; the recent files are still listed
// after a reload; presenter=1 gives the presenter layout, theme=light a light canvas; a
// second polygon chosen in the Open panel's gallery opens; the Export panel's SVG of Fig. 7's
// last step downloads, parses and draws the native CLI's triangles (NATIVE_LAST.svg is the
// native viewer's), its PNG sequence of monotone.json downloads frame by frame as the native
// viewer's --export-png-dir (NATIVE_FRAMES_DIR); the Shrink panel shrinks a failing
// sample in a Web Worker while frames go on, and its Save downloads a repro the native CLI
// reads back failing the same way; a forced crash of that worker (test-shrink-crash=N) leaves
// the page running with the panel saying so; Cancel ends the worker, and a shrink started
// after it finishes; the Edit panel's Save (Ctrl+S, Enter) downloads
// a polygon the native CLI triangulates as the original. DROP_FILE must have 5 vertices,
// PICK_FILE 3; BIG_FILE is a large face (its open and scan run in slices). Prints the time to
// the first frame.
import { execFileSync, spawn } from "node:child_process";
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { inflateSync } from "node:zlib";

const [url, nativePng, canvasArg, dropFile, pickFile, outDir, bigFile, nativeSvg, nativeFrames] = process.argv.slice(2);
const canvas = canvasArg.split(",").map(Number);  // x, y, w, h in pixels (scale 1)
const W = 1280, H = 800;
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
};

// ---- PNG: 8-bit RGB or RGBA, as Chromium and stb write them ----------------------------
function decodePng(buf) {
  let p = 8, width = 0, height = 0, channels = 0;
  const idat = [];
  while (p < buf.length) {
    const len = buf.readUInt32BE(p), type = buf.toString("latin1", p + 4, p + 8);
    const data = buf.subarray(p + 8, p + 8 + len);
    if (type === "IHDR") {
      width = data.readUInt32BE(0), height = data.readUInt32BE(4);
      if (data[8] !== 8 || data[12] !== 0) throw new Error("PNG: not 8-bit non-interlaced");
      channels = { 2: 3, 6: 4 }[data[9]];
      if (!channels) throw new Error("PNG: colour type " + data[9]);
    } else if (type === "IDAT") idat.push(data);
    p += 12 + len;
  }
  const raw = inflateSync(Buffer.concat(idat)), row = width * channels;
  const out = Buffer.alloc(width * height * 4);
  let prev = Buffer.alloc(row);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (row + 1)], line = Buffer.from(raw.subarray(y * (row + 1) + 1, (y + 1) * (row + 1)));
    for (let i = 0; i < row; i++) {
      const a = i >= channels ? line[i - channels] : 0, b = prev[i], c = i >= channels ? prev[i - channels] : 0;
      const pa = Math.abs(b - c), pb = Math.abs(a - c), pc = Math.abs(a + b - 2 * c);
      const pred = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][f];
      line[i] = (line[i] + pred) & 255;
    }
    for (let x = 0; x < width; x++)
      for (let k = 0; k < 4; k++)
        out[(y * width + x) * 4 + k] = k < channels ? line[x * channels + k] : 255;
    prev = line;
  }
  return { width, height, rgba: out };
}

// Pixels of the canvas rectangle (or `area`) that differ by more than `tolerance` in some channel.
function canvasDiff(a, b, tolerance = 24, area = canvas) {
  const [cx, cy, cw, ch] = area;
  let differ = 0;
  for (let y = cy; y < cy + ch; y++)
    for (let x = cx; x < cx + cw; x++) {
      const i = (y * a.width + x) * 4;
      for (let k = 0; k < 3; k++)
        if (Math.abs(a.rgba[i + k] - b.rgba[(y * b.width + x) * 4 + k]) > tolerance) { differ++; break; }
    }
  return differ / (cw * ch);
}
function colours(img) {  // distinct colours in the canvas rectangle
  const [cx, cy, cw, ch] = canvas, seen = new Set();
  for (let y = cy; y < cy + ch; y++)
    for (let x = cx; x < cx + cw; x++) seen.add(img.rgba.readUInt32BE((y * img.width + x) * 4));
  return seen.size;
}

// ---- Chromium and the DevTools protocol ----------------------------------------------
const profile = mkdtempSync(join(tmpdir(), "flood-web-chromium-"));
const chromium = spawn(process.env.CHROMIUM || "chromium", [
  "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
  "--remote-debugging-port=0", `--user-data-dir=${profile}`, `--window-size=${W},${H}`,
  "--force-device-scale-factor=1", "--no-first-run", "--disable-gpu-sandbox", "about:blank",
], { stdio: ["ignore", "ignore", "pipe"] });
const downloads = mkdtempSync(join(tmpdir(), "flood-web-downloads-"));
const cleanup = () => {
  chromium.kill();
  for (const d of [profile, downloads]) try { rmSync(d, { recursive: true, force: true }); } catch {}
};
process.on("exit", cleanup);
// FLOOD_WEB_TIMEOUT_S: longer for a 10^6-vertex big face (tests/web/run.sh's FLOOD_WEB_BIG).
const timeoutS = Number(process.env.FLOOD_WEB_TIMEOUT_S ?? 300);
setTimeout(() => { console.log(`FAIL the page test took over ${timeoutS} s`); process.exit(1); }, timeoutS * 1000).unref();

const browserWs = await new Promise((resolve, reject) => {
  let text = "";
  chromium.stderr.on("data", (d) => {
    text += d;
    const m = text.match(/DevTools listening on (ws:\/\/\S+)/);
    if (m) resolve(m[1]);
  });
  chromium.on("exit", (code) => reject(new Error("chromium exited " + code + ":\n" + text)));
});
const port = new URL(browserWs).port;
const pages = await (await fetch(`http://127.0.0.1:${port}/json/list`)).json();
const ws = new WebSocket(pages.find((t) => t.type === "page").webSocketDebuggerUrl);
await new Promise((resolve) => ws.addEventListener("open", resolve));
let nextId = 1;
const pending = new Map(), errors = [];
let chooserOpened = false;
const workers = new Map();  // the page's live Web Workers (auto-attached targets): session -> URL
ws.addEventListener("message", (e) => {
  const m = JSON.parse(e.data);
  if (m.id && pending.has(m.id)) {
    const { resolve, reject } = pending.get(m.id);
    pending.delete(m.id);
    m.error ? reject(new Error(JSON.stringify(m.error))) : resolve(m.result);
  } else if (m.method === "Page.fileChooserOpened") {
    chooserOpened = true;
  } else if (m.method === "Target.attachedToTarget" && m.params.targetInfo.type === "worker") {
    workers.set(m.params.sessionId, m.params.targetInfo.url);
  } else if (m.method === "Target.detachedFromTarget") {
    workers.delete(m.params.sessionId);
  } else if (m.method === "Runtime.consoleAPICalled" && m.params.type === "error") {
    errors.push("console.error: " + m.params.args.map((a) => a.value ?? a.description).join(" "));
  } else if (m.method === "Runtime.exceptionThrown") {
    errors.push("exception: " + (m.params.exceptionDetails.exception?.description ?? m.params.exceptionDetails.text));
  } else if (m.method === "Log.entryAdded" && m.params.entry.level === "error") {
    errors.push("log: " + m.params.entry.text + " " + (m.params.entry.url ?? ""));
  }
});
const send = (method, params = {}) => new Promise((resolve, reject) => {
  const id = nextId++;
  pending.set(id, { resolve, reject });
  ws.send(JSON.stringify({ id, method, params }));
});
const evaluate = async (expr) => (await send("Runtime.evaluate", { expression: expr, returnByValue: true })).result.value;
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
async function until(what, expr, test, ms = 90000) {
  const start = Date.now();
  for (;;) {
    let v;
    try { v = await evaluate(expr); } catch { v = undefined; }
    if (test(v)) return v;
    if (Date.now() - start > ms) { check(false, `${what} (last: ${JSON.stringify(v)})`); return v; }
    await sleep(100);
  }
}
// A new document (after a navigation) whose viewer has drawn its first frame.
async function navigate(query) {
  await evaluate("window.floodOldPage = true");
  await send("Page.navigate", { url: url + query });
  await until(`${query} draws its first frame`, "!window.floodOldPage && typeof Module === 'object' && Module._flood_web_frames ? Module._flood_web_frames() : 0", (v) => v >= 1);
  await settle(6);
}
const nativeFlood = process.env.NATIVE_FLOOD || "build/flood";
// Where the viewer drew the canvas (0), the caption (1), the Transcript's Copy button (2), the
// gallery's row i (3 + i).
const rect = (what) => evaluate(`[0, 1, 2, 3].map((k) => Module._flood_web_rect(${what}, k))`);
function commonest(img, [cx, cy, cw, ch]) {  // the canvas's most frequent colour: its background
  const count = new Map();
  for (let y = cy; y < cy + ch; y += 2)
    for (let x = cx; x < cx + cw; x += 2) {
      const v = img.rgba.readUInt32BE((y * img.width + x) * 4);
      count.set(v, (count.get(v) ?? 0) + 1);
    }
  const v = [...count].sort((a, b) => b[1] - a[1])[0][0];
  return [v >>> 24, (v >>> 16) & 255, (v >>> 8) & 255];
}
const luma = ([r, g, b]) => 0.299 * r + 0.587 * g + 0.114 * b;
const frames = () => until("a frame drawn", "typeof Module === 'object' && Module._flood_web_frames ? Module._flood_web_frames() : -1", (v) => v >= 0);
async function settle(n = 4) {  // n more frames drawn
  const f = await frames();
  await until(`${n} more frames`, "Module._flood_web_frames()", (v) => v >= f + n);
}
async function screenshot(name) {
  const { data } = await send("Page.captureScreenshot", { format: "png" });
  const buf = Buffer.from(data, "base64");
  writeFileSync(join(outDir, name), buf);
  return decodePng(buf);
}
// Held for two frames: ImGui 1.86 sees a key only while it is down at a frame (the arrows go
// through the viewer's own key queue, which keeps every press).
async function click([x, y, w, h]) {  // the middle of a rectangle the viewer drew
  // A frame between the events: ImGui sees the pointer over the item, then the press, then
  // the release (a button or a Selectable acts on release).
  const [cx, cy] = [x + w / 2, y + h / 2];
  await send("Input.dispatchMouseEvent", { type: "mouseMoved", x: cx, y: cy });
  await settle(2);
  for (const type of ["mousePressed", "mouseReleased"]) {
    await send("Input.dispatchMouseEvent", { type, x: cx, y: cy, button: "left", clickCount: 1 });
    await settle(2);
  }
}
async function key(name, code, modifiers = 0) {
  for (const type of ["keyDown", "keyUp"]) {
    await send("Input.dispatchKeyEvent", { type, modifiers, key: name, code: name.length === 1 ? "Key" + name.toUpperCase() : name,
                                          windowsVirtualKeyCode: code, nativeVirtualKeyCode: code });
    await settle(type === "keyDown" ? 2 : 4);
  }
}
const step = () => evaluate("Module._flood_web_step()");

await send("Runtime.enable");
await send("Log.enable");
await send("Page.enable");
await send("Emulation.setDeviceMetricsOverride", { width: W, height: H, deviceScaleFactor: 1, mobile: false });

// ---- the URL's polygon at the URL's step -------------------------------------------------
const t0 = Date.now();
await send("Page.navigate", { url: url + "?polygon=paper-figure-7.json&step=23" });
await until("the first frame", "typeof Module === 'object' && Module._flood_web_frames ? Module._flood_web_frames() : 0", (v) => v >= 1);
console.log(`time to first frame: ${((Date.now() - t0) / 1000).toFixed(2)} s`);
await settle(6);
check(await step() === 23, `the URL's step=23 is shown (step ${await step()})`);
check((await evaluate("document.title")).includes("paper-figure-7.json"), "the title names paper-figure-7.json");
const native = decodePng(readFileSync(nativePng));
const at23 = await screenshot("page-step-23.png");
check(at23.width === W && at23.height === H, `the page is ${W}x${H} (${at23.width}x${at23.height})`);
const c = colours(native);
check(c > 3, `the native canvas is a picture (${c} colours)`);
const d23 = canvasDiff(at23, native);
check(d23 < 0.02, `the canvas matches the native viewer's at step 23 (${(d23 * 100).toFixed(2)} % of pixels differ)`);

// ---- arrow keys ----------------------------------------------------------------------------
await key("ArrowRight", 39);
check(await step() === 24, `ArrowRight: step 24 (step ${await step()})`);
const at24 = await screenshot("page-step-24.png");
const moved = canvasDiff(at24, at23, 0);
check(moved > 0.0005, `ArrowRight changes the picture (${(moved * 100).toFixed(2)} % of pixels)`);
await key("ArrowLeft", 37);
await key("ArrowLeft", 37);
check(await step() === 22, `ArrowLeft twice: step 22 (step ${await step()})`);

// ---- Save PNG reaches the user as a download -------------------------------------------------
try {
  await send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: downloads });
} catch {
  await send("Page.setDownloadBehavior", { behavior: "allow", downloadPath: downloads });
}
const normalCanvas = await rect(0);
await key("p", 80);
const pngName = "paper-figure-7-step22.png";
await until(`P downloads ${pngName}`, "0", () => existsSync(join(downloads, pngName)), 30000);
if (existsSync(join(downloads, pngName))) {
  const bytes = readFileSync(join(downloads, pngName));
  check(bytes.subarray(0, 8).equals(Buffer.from([137, 80, 78, 71, 13, 10, 26, 10])), "the download is a PNG");
  const png = decodePng(bytes);
  const [w, h] = [Math.round(normalCanvas[2]), Math.round(normalCanvas[3])];
  check(png.width === w && png.height === h, `the PNG is the canvas's size, ${w}x${h} (${png.width}x${png.height})`);
  const seen = new Set();
  for (let i = 0; i < png.rgba.length; i += 4) seen.add(png.rgba.readUInt32BE(i));
  check(seen.size > 3, `the PNG is a picture (${seen.size} colours)`);
}
check(readdirSync(downloads).length === 1, `one file downloaded (${readdirSync(downloads).join(", ")})`);

// ---- Copy reaches the browser's clipboard ----------------------------------------------------
const origin = new URL(url).origin;
await send("Browser.grantPermissions", { origin, permissions: ["clipboardReadWrite", "clipboardSanitizedWrite"] });
await send("Emulation.setFocusEmulationEnabled", { enabled: true });
const expected = execFileSync(nativeFlood, ["transcript", "polygons/paper-figure-7.json"], { encoding: "utf8" }).trim();
const copyButton = await rect(2);
check(copyButton[2] > 0, `the Transcript panel's Copy button is shown (${copyButton.join(",")})`);
if (copyButton[2] > 0) {
  await click(copyButton);
  const copied = await until("Copy hands the transcript to the browser", "Module.floodCopied", (v) => typeof v === "string", 10000);
  const board = (await send("Runtime.evaluate", { expression: "navigator.clipboard.readText()", awaitPromise: true, returnByValue: true })).result.value;
  check(copied === expected && board === expected,
        `the clipboard holds the native flood transcript (${JSON.stringify(board?.slice(0, 40))}...)`);
}

// ---- a dropped file --------------------------------------------------------------------------
const name = dropFile.split("/").pop();
const [x, y] = [canvas[0] + canvas[2] / 2, canvas[1] + canvas[3] / 2];
const data = { items: [], files: [dropFile], dragOperationsMask: 1 };
for (const type of ["dragEnter", "dragOver", "drop"])
  await send("Input.dispatchDragEvent", { type, x, y, data });
await until(`the dropped ${name} opens`, "document.title", (t) => typeof t === "string" && t.includes(name), 30000);
await settle();
check(await evaluate("Module._flood_web_vertices()") === 5, `the dropped polygon has its 5 vertices (${await evaluate("Module._flood_web_vertices()")})`);
await screenshot("page-dropped.png");

// ---- the file picker -----------------------------------------------------------------------
await send("Page.setInterceptFileChooserDialog", { enabled: true });
await key("o", 79, 2);  // Ctrl+O
await until("Ctrl+O opens the file picker", "0", () => chooserOpened, 10000);
const picked = pickFile.split("/").pop();
const { root } = await send("DOM.getDocument");
const { nodeId } = await send("DOM.querySelector", { nodeId: root.nodeId, selector: "#picker" });
await send("DOM.setFileInputFiles", { nodeId, files: [pickFile] });
await until(`the picked ${picked} opens`, "document.title", (t) => typeof t === "string" && t.includes(picked), 30000);
await settle();
check(await evaluate("Module._flood_web_vertices()") === 3, `the picked polygon has its 3 vertices (${await evaluate("Module._flood_web_vertices()")})`);
await screenshot("page-picked.png");

// ---- background work in slices: a large face's invariant scan never holds the page still ------
if (bigFile) {
  const big = bigFile.split("/").pop();
  const bigWait = timeoutS * 1000;  // a 10^6-vertex face (FLOOD_WEB_BIG) opens in minutes
  const scanFramesBefore = await evaluate("Module._flood_web_scan_frames()");
  for (const type of ["dragEnter", "dragOver", "drop"])
    await send("Input.dispatchDragEvent", { type, x, y, data: { items: [], files: [bigFile], dragOperationsMask: 1 } });
  // Until its outline is shown (the title names it): the read and the outline's preparation.
  const dropped = Date.now();
  let readStall = 0, title = "";
  for (let polled = Date.now(); Date.now() - dropped < bigWait; polled = Date.now()) {
    title = await evaluate("document.title");
    readStall = Math.max(readStall, Date.now() - polled);
    if (typeof title === "string" && title.includes(big)) break;
    await new Promise((r) => setTimeout(r, 20));
  }
  check(typeof title === "string" && title.includes(big), `the dropped ${big} opens (its outline after ${Date.now() - dropped} ms; the page's longest stall meanwhile ${readStall} ms)`);
  // The open itself runs in steps (read, validate, the flood in slices, check, the preparation
  // in parts): its outline comes first, and frames go on until the run is adopted. The longest
  // wait for an answer from the page is reported (a figure, not a test: docs/BENCHMARKS.md).
  let openFrames = null, openFirst = null, openLast = null, stall = 0, polled = Date.now();
  const openStart = polled;
  for (const start = Date.now(); Date.now() - start < bigWait;) {
    const [opening, frames] = await evaluate("[Module._flood_web_opening(), Module._flood_web_frames()]");
    stall = Math.max(stall, Date.now() - polled);
    if (openFirst === null) openFirst = frames;
    openLast = frames;
    if (opening !== 1) break;
    await new Promise((r) => setTimeout(r, 20));
    polled = Date.now();
  }
  openFrames = openLast - openFirst;
  check(await evaluate("Module._flood_web_opening()") === 0, `the open of ${big} ends`);
  check(await evaluate("Module._flood_web_steps()") > 0, `${big} is flooded (${await evaluate("Module._flood_web_steps()")} steps)`);
  check(openFrames >= 1, `frames are drawn between ${big}'s outline and its flooded run (${openFrames} frames in ${Date.now() - openStart} ms; the page's longest stall ${stall} ms)`);
  // Frames go on between the scan's slices: the page counts those drawn while it runs.
  for (const start = Date.now(); Date.now() - start < bigWait;) {
    if (await evaluate("Module._flood_web_scanning()") !== 1) break;
    await new Promise((r) => setTimeout(r, 20));
  }
  const scanFrames = await evaluate("Module._flood_web_scan_frames()") - scanFramesBefore;
  check(await evaluate("Module._flood_web_scanning()") === 0, `the invariant scan of ${big} ends`);
  check(scanFrames >= 2, `frames are drawn while the invariant scan runs (${scanFrames} frames during it)`);
}

// ---- settings and recent files persist across a reload (IndexedDB) ----------------------------
// The open's write-back started in the frames the pick's settle() waited for: once none is
// running, the list is in IndexedDB.
await until("the recent files written back to the browser's storage",
            "Module.floodPersisted && !Module.floodPersisted.running ? Module.floodPersisted.saved : 0", (v) => v >= 1, 10000);
const recent = async () => (await evaluate(`Array.from({ length: 10 }, (_, i) => Module.UTF8ToString(Module._flood_web_recent(i)))`) ?? []).filter((f) => f);
const before = await recent();
check(before.some((f) => f.endsWith(picked)), `the picked file is a recent file (${before.join(", ")})`);

// ---- presenter mode from the URL (the reload) -----------------------------------------------
await navigate("?polygon=paper-figure-7.json&presenter=1");
const after = await recent();
check(after.some((f) => f.endsWith(picked)) && after.some((f) => f.endsWith(name)),
      `after a reload the recent files still list ${picked} and ${name} (${after.join(", ")})`);
check(await evaluate("Module._flood_web_presenter()") === 1, "presenter=1: presenter mode");
const pc = await rect(0), cap = await rect(1);
check(normalCanvas[2] < W && pc[0] === 0 && pc[2] === W,
      `presenter=1: the canvas spans the window's width, ${W} (${pc[2]}; ${normalCanvas[2]} with the panels)`);
check(cap[2] > 0 && Math.abs(cap[1] + cap[3] - H) <= 1 && Math.abs(pc[1] + pc[3] - cap[1]) <= 1,
      `presenter=1: the caption is the band under the canvas (caption ${cap.join(",")})`);
await screenshot("page-presenter.png");

// ---- light theme from the URL --------------------------------------------------------------
const dark = luma(commonest(at23, canvas));
await navigate("?polygon=paper-figure-7.json&theme=light");
const light = luma(commonest(await screenshot("page-light.png"), await rect(0)));
check(dark < 80 && light > 200, `theme=light: the canvas's background is light (luma ${light.toFixed(0)}; dark ${dark.toFixed(0)})`);

// ---- the gallery: a second polygon chosen in the Open panel --------------------------------
const gallery = JSON.parse(readFileSync("polygons/gallery.json", "utf8"));
await navigate("?polygon=gallery.json");
check((await evaluate("document.title")).includes(gallery[0].file), `gallery.json opens ${gallery[0].file}`);
const first = [await evaluate("Module._flood_web_vertices()"), await evaluate("Module._flood_web_steps()")];
const row = await rect(4);
check(row[2] > 0, `the Open panel shows the gallery's second row (${row.join(",")})`);
if (row[2] > 0) {
  await click(row);
  await until(`clicking the second row opens ${gallery[1].file}`, "document.title",
              (t) => typeof t === "string" && t.includes(gallery[1].file), 30000);
  await settle();
  const second = [await evaluate("Module._flood_web_vertices()"), await evaluate("Module._flood_web_steps()")];
  check(second[0] !== first[0] || second[1] !== first[1],
        `the second gallery polygon is another flood (vertices, steps: ${first} then ${second})`);
  await screenshot("page-gallery.png");
}

// ---- the Export panel's downloads, read back as a user would --------------------------------------
// The toolbar's Export... opens the panel, the format is chosen in its combo's list, then
// Export. The SVG parses as XML (in the browser) and holds the very triangles of the native
// flood triangulate; the PNG sequence's frames decode at the export's size, one per step as
// the native viewer's --export-png-dir gives them, each its own picture and the native one's.
const exportControl = (which) => evaluate(`[0, 1, 2, 3].map((k) => Module._flood_web_export_rect(${which}, k))`);
const exportNote = () => evaluate("Module.UTF8ToString(Module._flood_web_export_note())");
const [OPENER, COMBO, EXPORT_BUTTON, FIRST_FORMAT] = [0, 1, 2, 4];  // viewer/panel_export.cpp
const [SVG_FORMAT, PNG_SEQUENCE] = [1, 3];                           // its kFormatNames
async function exportAs(format, what) {  // the export's note once it has ended ("" when not)
  const opener = await exportControl(OPENER);
  check(opener[2] > 0, `${what}: the toolbar's Export... button is shown (${opener.join(",")})`);
  if (!(opener[2] > 0)) return "";
  await click(opener);
  const shown = (which) => `[0, 1, 2, 3].map((k) => Module._flood_web_export_rect(${which}, k))`;
  const combo = await until(`${what}: the Export panel shows its format combo`, shown(COMBO), (r) => r?.[2] > 0, 10000);
  if (!(combo?.[2] > 0)) return "";
  await click(combo);
  const item = await until(`${what}: the combo lists format ${format}`, shown(FIRST_FORMAT + format), (r) => r?.[2] > 0, 10000);
  if (!(item?.[2] > 0)) return "";
  await click(item);
  const go = await exportControl(EXPORT_BUTTON);
  check(go[2] > 0, `${what}: the Export button is shown (${go.join(",")})`);
  if (!(go[2] > 0)) return "";
  await click(go);
  return until(`${what}: the panel says how the export ended`, "Module.UTF8ToString(Module._flood_web_export_note())", (n) => typeof n === "string" && n !== "", 60000);
}

// The SVG of Fig. 7's last step: all of its triangles.
const exportStart = Date.now();  // what these sections add to the test (docs/BENCHMARKS.md)
await navigate("?polygon=paper-figure-7.json&step=99999");
const lastStep = await step();
const svgName = `paper-figure-7-step${lastStep}.svg`;
const svgNote = await exportAs(SVG_FORMAT, "the SVG export");
check(svgNote === `wrote ${svgName}`, `the Export panel says it wrote ${svgName} (${JSON.stringify(svgNote)})`);
await until(`the SVG export downloads ${svgName} (${svgNote})`, "0", () => existsSync(join(downloads, svgName)), 30000);
if (existsSync(join(downloads, svgName))) {
  const text = readFileSync(join(downloads, svgName), "utf8");
  const read = await evaluate(`(() => {
    const doc = new DOMParser().parseFromString(${JSON.stringify(text)}, "image/svg+xml");
    const error = doc.querySelector("parsererror");
    if (error) return { error: error.textContent };
    const svg = doc.documentElement, land = doc.querySelector("path[fill-rule=evenodd]");
    return { root: svg.localName, size: [svg.getAttribute("width"), svg.getAttribute("height")],
             ring: land ? land.getAttribute("d") : "",
             triangles: [...doc.querySelectorAll("polygon")].map((p) => p.getAttribute("points")) };
  })()`);
  check(read && !read.error && read.root === "svg", `the SVG download parses as SVG (${read?.error ?? read?.root})`);
  check(read?.size?.join("x") === "1280x800", `the SVG is the panel's size, 1280x800 (${read?.size?.join("x")})`);
  // Its triangles' corners are the polygon's (the land's path, vertex by vertex): as vertex
  // numbers, they must be the native CLI's triangles.
  const tri = JSON.parse(execFileSync(nativeFlood, ["triangulate", "polygons/paper-figure-7.json", "-o", "-"], { encoding: "utf8" }));
  const corners = (read?.ring ?? "").match(/-?[0-9.]+(?:e[-+]?[0-9]+)?/g) ?? [];
  const vertexAt = new Map();
  for (let i = 0; i + 1 < corners.length; i += 2) vertexAt.set(`${corners[i]},${corners[i + 1]}`, i / 2);
  check(vertexAt.size === tri.vertices.length, `the SVG's land has the polygon's ${tri.vertices.length} vertices (${vertexAt.size})`);
  const key = (t) => [...t].sort((a, b) => a - b).join(" ");
  const drawn = (read?.triangles ?? []).map((p) => key(p.trim().split(/\s+/).map((xy) => vertexAt.get(xy) ?? -1))).sort();
  const made = tri.triangles.map(key).sort();
  check(drawn.length === made.length && drawn.every((t, i) => t === made[i]),
        `the SVG draws the native flood triangulate's ${made.length} triangles (${drawn.length} drawn, ${drawn.filter((t, i) => t !== made[i]).length} differ)`);
  check(text === readFileSync(nativeSvg, "utf8"), "the SVG download is the native flood-viewer --screenshot OUT.svg's, byte for byte");
}

// A PNG sequence of monotone.json: its frames arrive as downloads, one file each.
await navigate("?polygon=monotone.json");
const nativeNames = readdirSync(nativeFrames).filter((f) => f.endsWith(".png")).sort();
const monotoneSteps = await evaluate("Module._flood_web_steps()");
check(nativeNames.length === monotoneSteps + 1, `the native sequence has a frame per step, 0..${monotoneSteps} (${nativeNames.length} frames)`);
const seqNote = await exportAs(PNG_SEQUENCE, "the PNG sequence export");
check(seqNote === `wrote ${nativeNames.length} frames in monotone-frames`,
      `the Export panel says it wrote ${nativeNames.length} frames (${JSON.stringify(seqNote)})`);
await until(`the PNG sequence downloads ${nativeNames.length} frames (${seqNote})`, "0",
            () => nativeNames.every((f) => existsSync(join(downloads, f))), 30000);
const gotNames = readdirSync(downloads).filter((f) => /^frame-/.test(f)).sort();
check(gotNames.join() === nativeNames.join(), `the downloads are the frames ${nativeNames[0]}..${nativeNames.at(-1)} (${gotNames.join(", ")})`);
let previous = null;
for (const f of nativeNames.filter((n) => existsSync(join(downloads, n)))) {
  const bytes = readFileSync(join(downloads, f));
  const isPng = bytes.subarray(0, 8).equals(Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]));
  const png = isPng ? decodePng(bytes) : null, theirs = decodePng(readFileSync(join(nativeFrames, f)));
  check(png && png.width === theirs.width && png.height === theirs.height,
        `${f} is a PNG of the native frame's size, ${theirs.width}x${theirs.height} (${png ? png.width + "x" + png.height : "not a PNG"})`);
  if (!png || png.width !== theirs.width || png.height !== theirs.height) continue;
  const whole = [0, 0, png.width, png.height];
  const d = canvasDiff(png, theirs, 24, whole);
  check(d < 0.02, `${f} matches the native viewer's (${(d * 100).toFixed(2)} % of pixels differ)`);
  if (previous) {
    const moved = canvasDiff(png, previous, 0, whole);
    check(moved > 0.0005, `${f} differs from the frame before it (${(moved * 100).toFixed(2)} % of pixels)`);
  }
  previous = png;
}

console.log(`the Export sections took ${((Date.now() - exportStart) / 1000).toFixed(1)} s`);

// ---- the Shrink panel: the shrink runs in a Web Worker (viewer/shrink_worker.h) ------------------
// A failing sample shrinks while the page goes on drawing frames; Save offers the repro as a
// download, and the native CLI reads it back failing as the original does.
const shrinkStart = Date.now();  // what these sections add to the test (docs/BENCHMARKS.md)
const shrinkButton = (which) => evaluate(`[0, 1, 2, 3].map((k) => Module._flood_web_shrink_rect(${which}, k))`);
const shrinkNote = () => evaluate("Module.UTF8ToString(Module._flood_web_shrink_note())");
const sample = "polygons/tutorial/crossing-face.json";
// How the native `flood triangulate --no-validate` fails on a file: its exit code and the name
// of the forbidden transition (or the checker's rejection) in its message.
function nativeFailure(file) {
  try {
    execFileSync(nativeFlood, ["triangulate", "--no-validate", file, "-o", join(profile, "triangulated.json")], { encoding: "utf8", stdio: "pipe" });
    return "ok";
  } catch (e) {
    const m = /forbidden transition \w+|exact checker rejects/.exec(e.stderr) || [e.stderr.split("\n")[0]];
    return `exit ${e.status}: ${m[0]}`;
  }
}
async function startShrink(query) {
  await navigate(query);
  return pressShrink();
}
async function pressShrink() {
  const button = await until("the Shrink panel's Shrink button is shown", "Module._flood_web_shrink_rect(0, 2)", (v) => v > 0, 20000);
  if (!(button > 0)) return false;
  // click() without its last frames: the shrink may be over by then.
  const [x, y, w, h] = await shrinkButton(0);
  await send("Input.dispatchMouseEvent", { type: "mouseMoved", x: x + w / 2, y: y + h / 2 });
  await settle(2);
  await send("Input.dispatchMouseEvent", { type: "mousePressed", x: x + w / 2, y: y + h / 2, button: "left", clickCount: 1 });
  await settle(2);
  await send("Input.dispatchMouseEvent", { type: "mouseReleased", x: x + w / 2, y: y + h / 2, button: "left", clickCount: 1 });
  return true;
}
// Frames drawn while the shrink runs (its Cancel button shown), until the panel's note says
// how it ended.
async function shrinkRuns(what, countFrames = true) {
  let first = null, last = null, running = 0;
  for (const start = Date.now(); Date.now() - start < 60000;) {
    const [note, cancel, frames] = await evaluate("[Module.UTF8ToString(Module._flood_web_shrink_note()), Module._flood_web_shrink_rect(1, 2), Module._flood_web_frames()]");
    if (note) break;
    if (cancel > 0) { running++; if (first === null) first = frames; last = frames; }
    await sleep(20);
  }
  const note = await shrinkNote();
  check(note !== "", `${what}: the Shrink panel says how it ended (${JSON.stringify(note)})`);
  if (countFrames) check(first !== null && last - first >= 2, `${what}: frames are drawn while the worker shrinks (${first === null ? "no running shrink seen" : last - first + " frames"})`);
  return note;
}
const sampleFailure = nativeFailure(sample);
// test-shrink-slow=20: each try about 20 ms longer, so the shrink lasts a second or two however
// fast the machine, and the frames counted while it runs are not a race.
if (await startShrink("?polygon=tutorial/crossing-face.json&test-shrink-slow=20")) {
  const before = await evaluate("Module._flood_web_vertices()");
  const note = await shrinkRuns("crossing-face.json's shrink");
  const after = await evaluate("Module._flood_web_vertices()");
  check(note.startsWith(`shrunk ${before} -> ${after} vertices`) && after < before,
        `the shrink opens a smaller repro (${before} -> ${after} vertices)`);
  await settle();
  const save = await shrinkButton(2);
  check(save[2] > 0, `the repro's Save button is shown (${save.join(",")})`);
  const reproName = "crossing-face-shrunk.geojson";
  if (save[2] > 0) {
    await click(save);
    await until(`Save downloads ${reproName}`, "0", () => existsSync(join(downloads, reproName)), 30000);
  }
  if (existsSync(join(downloads, reproName))) {
    const repro = join(downloads, reproName);
    const back = nativeFailure(repro);
    check(back === sampleFailure && back !== "ok",
          `the downloaded repro fails in the native flood triangulate as ${sample} does (${back}; the original: ${sampleFailure})`);
    const read = JSON.parse(readFileSync(repro, "utf8"));
    const count = JSON.stringify(read).match(/\[-?[0-9.e+-]+,-?[0-9.e+-]+\]/g)?.length ?? 0;
    check(count >= after && count <= after + 1, `the download holds the repro's ${after} vertices (${count} positions)`);
  }
}

// ---- a crash in the shrink's worker ends only the worker ----------------------------------------
// The test-only test-shrink-crash=N makes the worker's CLI abort at its Nth clock reading.
if (await startShrink("?polygon=tutorial/crossing-face.json&test-shrink-crash=30")) {
  const before = await evaluate("Module._flood_web_vertices()");
  const note = await shrinkRuns("the crashing shrink", false);
  check(note.startsWith("the shrink stopped with a crash") && note.includes("forced crash"),
        `the Shrink panel says the shrink stopped with a crash (${JSON.stringify(note)})`);
  const f = await frames();
  await settle(4);
  check(await frames() >= f + 4, "the page goes on drawing frames after the worker's crash");
  check(await evaluate("Module._flood_web_vertices()") === before, `the polygon shown is unchanged (${before} vertices)`);
  check(await evaluate("Module._flood_web_shrink_rect(0, 2)") > 0, "the Shrink button is offered again");
}

// ---- the Shrink panel's Cancel ends the worker; a shrink started afterwards finishes ------------
const cancelStart = Date.now();
// test-shrink-slow=200: a shrink of many seconds (about 85 tries of 200 ms), still running
// when Cancel is pressed. The page's Web Workers are seen over the DevTools protocol
// (auto-attached targets of type worker).
await send("Target.setAutoAttach", { autoAttach: true, waitForDebuggerOnStart: false, flatten: true });
const shrinkWorkers = () => [...workers.values()].filter((u) => u.endsWith("/shrink-worker.js")).length;
if (await startShrink("?polygon=tutorial/crossing-face.json&test-shrink-slow=200")) {
  const before = await evaluate("Module._flood_web_vertices()");
  const cancel = await until("the running shrink shows its Cancel button", "[0, 1, 2, 3].map((k) => Module._flood_web_shrink_rect(1, k))", (r) => r?.[2] > 0, 20000);
  await until("a shrink's worker starts", "0", () => shrinkWorkers() > 0, 10000);
  check(shrinkWorkers() === 1, `the shrink runs in one Web Worker (${[...workers.values()].join(", ")})`);
  // A few tries in (a worker still loading its wasm has reported none: the note then says so,
  // which is right too, but says less).
  await sleep(1500);
  if (cancel?.[2] > 0) await click(cancel);
  const note = await until("Cancel: the Shrink panel says how the shrink ended", "Module.UTF8ToString(Module._flood_web_shrink_note())", (n) => typeof n === "string" && n !== "", 10000);
  check(/^shrink cancelled (after \d+ tries|before its first progress report)/.test(note), `Cancel: the Shrink panel says the shrink was cancelled (${JSON.stringify(note)})`);
  await until("Cancel ends the shrink's worker", "0", () => shrinkWorkers() === 0, 10000);
  check(shrinkWorkers() === 0, `Cancel ends the shrink's Web Worker (${shrinkWorkers()} left)`);
  const f = await frames();
  await settle(4);
  check(await frames() >= f + 4, "the page goes on drawing frames after Cancel");
  check(await evaluate("Module._flood_web_vertices()") === before, `Cancel leaves the polygon shown unchanged (${before} vertices)`);
  // The page reads test-shrink-slow from its URL at each Shrink: the second one as the first
  // section's, 20 ms a reading.
  await evaluate("history.replaceState(null, '', location.search.replace('test-shrink-slow=200', 'test-shrink-slow=20'))");
  if (await pressShrink()) {
    await until("a second Shrink starts", "Module.UTF8ToString(Module._flood_web_shrink_note())", (n) => typeof n === "string" && !n.startsWith("shrink cancelled"), 10000);
    const again = await shrinkRuns("the shrink after a cancelled one");
    const after = await evaluate("Module._flood_web_vertices()");
    check(again.startsWith(`shrunk ${before} -> ${after} vertices`) && after < before,
          `the shrink after a cancelled one opens its repro (${JSON.stringify(again)})`);
    await until("the finished shrink's worker ends", "0", () => shrinkWorkers() === 0, 10000);
  }
}

console.log(`the Shrink Cancel section took ${((Date.now() - cancelStart) / 1000).toFixed(1)} s`);

// ---- the Edit panel's Save reaches the user as a download ----------------------------------------
// Ctrl+S opens the Save window (at the canvas's corner + 60 px, default ImGui style: its path
// field is the first row under a 19 px title bar); Enter in the field saves. The download,
// read by the native CLI, floods to the very triangles of the polygon it was saved from.
await navigate("?polygon=paper-figure-7.json");
// ImGui 1.86 takes Ctrl from the Control key's own events, not from a key's modifiers.
const control = (type) => send("Input.dispatchKeyEvent", { type, modifiers: type === "keyDown" ? 2 : 0, key: "Control", code: "ControlLeft", windowsVirtualKeyCode: 17, nativeVirtualKeyCode: 17 });
await control("keyDown");
await settle(2);
await key("s", 83, 2);
await control("keyUp");
await settle(2);
const field = await rect(0);
await click([field[0] + 60 + 8, field[1] + 60 + 19 + 8, 300, 19]);
await key("Enter", 13);
const savedName = "paper-figure-7-edited.json";
await until(`the Edit panel's Save downloads ${savedName}`, "0", () => existsSync(join(downloads, savedName)), 30000);
if (existsSync(join(downloads, savedName))) {
  const tri = (file, out) => {
    try { execFileSync(nativeFlood, ["triangulate", file, "-o", out], { stdio: "pipe" }); return 0; } catch (e) { return e.status; }
  };
  const [a, b] = [join(profile, "original-triangles.json"), join(profile, "saved-triangles.json")];
  const codes = [tri("polygons/paper-figure-7.json", a), tri(join(downloads, savedName), b)];
  check(codes[0] === 0 && codes[1] === 0 && readFileSync(a).equals(readFileSync(b)),
        `the saved polygon opens with the native flood triangulate, to the original's triangles (exit codes ${codes})`);
}

console.log(`the Shrink and Edit sections took ${((Date.now() - shrinkStart) / 1000).toFixed(1)} s`);
check(errors.length === 0, "no console error" + (errors.length ? ":\n  " + errors.join("\n  ") : ""));
ws.close();
console.log(failures ? `page test: ${failures} failed` : "page test: all passed");
process.exit(failures ? 1 : 0);
