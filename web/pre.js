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
Module["preRun"] = (Module["preRun"] || []).concat(function () {
  ENV.FLOOD_POLYGONS_DIR = "/polygons";  // the gallery and samples (viewer/model.cpp)
  ENV.HOME = "/home/web_user";           // recent files and settings (in memory for now)
});
