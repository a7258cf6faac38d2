// The page's arguments (cmake/web.cmake passes this with --pre-js): the URL's query is the
// command line, so a link on a slide opens a polygon at a step:
//   index.html?polygon=paper-figure-7.json&step=23&presenter=1&theme=light
// A polygon is a file of polygons/ (preloaded as /polygons); an unknown parameter is ignored.
Module["arguments"] = Module["arguments"] || (function () {
  const q = new URLSearchParams(typeof location === "object" ? location.search : "");
  const args = [];
  const polygon = q.get("polygon");
  if (polygon) args.push(polygon.startsWith("/") ? polygon : "/polygons/" + polygon);
  for (const step of q.getAll("step")) args.push("--step", step);
  if (q.get("feature")) args.push("--feature", q.get("feature"));
  if (q.get("up")) args.push("--up", q.get("up"));
  if (q.get("theme")) args.push("--theme", q.get("theme"));
  const on = (v) => v !== null && v !== "0" && v !== "false";
  if (on(q.get("presenter"))) args.push("--presenter");
  if (on(q.get("predicates"))) args.push("--predicates");
  return args;
})();
// Settings and recent files ($HOME/.config/flood-viewer, viewer/main.cpp) persist across
// reloads in the browser's IndexedDB: the folder is read from there before main starts, and
// written back each time the viewer has written it (platform::persistConfig calls
// Module.floodPersistConfig). Without IndexedDB (a private window may refuse it) they last
// until the page is reloaded, as before.
const floodConfig = "/home/web_user/.config/flood-viewer";
Module["preRun"] = (Module["preRun"] || []).concat(function () {
  ENV.FLOOD_POLYGONS_DIR = "/polygons";  // the gallery and samples (viewer/model.cpp)
  ENV.HOME = "/home/web_user";
  FS.mkdirTree(floodConfig);
  try {
    FS.mount(IDBFS, {}, floodConfig);
  } catch (e) {
    console.warn("flood-viewer: settings will not persist: " + e);
    return;
  }
  addRunDependency("flood-config");
  FS.syncfs(true, (err) => {
    if (err) console.warn("flood-viewer: saved settings not read: " + err);
    removeRunDependency("flood-config");
  });
});
// One write-back at a time; a write during one asks for another after it. `saved` counts
// the write-backs finished (the page test waits for it before reloading).
Module["floodPersistConfig"] = function () {
  const p = Module["floodPersisted"] = Module["floodPersisted"] || { running: false, again: false, saved: 0 };
  if (p.running) { p.again = true; return; }
  p.running = true;
  const sync = () => FS.syncfs(false, (err) => {
    if (err) console.warn("flood-viewer: settings not saved in the browser: " + err);
    if (p.again) { p.again = false; sync(); return; }
    p.running = false;
    p.saved++;
  });
  sync();
};
