#!/usr/bin/env bash
# Regenerates the images of docs/TUTORIAL.md with the viewer's own --screenshot, never by hand:
#
#   scripts/tutorial-images.sh [BUILD_DIR]      (default: build; needs xvfb-run without a display)
#
# Each image is the viewer at the step just after the N-th event of a kind, found with
# `flood transcript --narrate`, so the pictures follow the machine if it changes.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
FLOOD=$BUILD/flood
VIEWER=$BUILD/flood-viewer
[ -x "$FLOOD" ] && [ -x "$VIEWER" ] || {
  echo "build first: cmake -S . -B $BUILD && cmake --build $BUILD (flood and flood-viewer)" >&2
  exit 2
}
# The pictures do not follow this machine's saved viewer theme (--screenshot reads it).
XDG_CONFIG_HOME=$(mktemp -d)
export XDG_CONFIG_HOME
trap 'rm -rf "$XDG_CONFIG_HOME"' EXIT
RUN=()
if [ -z "${DISPLAY:-}" ]; then RUN=(xvfb-run -a -s "-screen 0 1280x800x24"); fi
mkdir -p docs/img

# step_after FILE ACTION N: the viewer step showing the N-th ACTION event (1-based; 0 = last
# event of the run).
step_after() {
  { "$FLOOD" transcript --narrate --no-validate "polygons/$1" 2>/dev/null || true; } |
    awk -v a="$2" -v n="$3" '
      { split($2, s, ":"); last = s[1] }
      $3 == a":" && ++k == n { print s[1]; found = 1; exit }
      END { if (!found && n == 0) print last }' | tr -d ':'
}

# shot NAME FILE ACTION N
shot() {
  local step
  step=$(step_after "$2" "$3" "$4")
  [ -n "$step" ] || { echo "no $3 #$4 in $2" >&2; exit 1; }
  viewer "polygons/$2" --step "$step" --screenshot "docs/img/$1.png" --size 900x600
}

# viewer ARGS...: the picture is written whatever the input; exit codes 3-6 only say the
# input failed (invalid polygons are pictured on purpose), anything else stops the script.
viewer() {
  local rc=0
  "${RUN[@]}" "$VIEWER" "$@" || rc=$?
  [ "$rc" -eq 0 ] || { [ "$rc" -ge 3 ] && [ "$rc" -le 6 ]; } || exit "$rc"
}

shot monotone-fill            monotone.json         Fill   1
shot two-gorges-spill         two-gorges.json       Spill  1
shot two-gorges-jump          two-gorges.json       Jump   1
shot sag-bridge               sag.json              Bridge 1
shot pending-bottoms          pending-bottoms.json  Bridge 2
shot hole-spill               hole.json             Spill  1
shot hole-jump                hole.json             Jump   1
shot touching-hole            touching-hole.json    Fill   2
shot horizontal               horizontal.json       Jump   1
shot figure7-1-spill          paper-figure-7.json   Spill  1
shot figure7-2-jump           paper-figure-7.json   Jump   1
shot figure7-3-jump           paper-figure-7.json   Jump   2
shot figure7-4-bridge         paper-figure-7.json   Bridge 2
shot figure7-5-fill           paper-figure-7.json   Fill   2
shot figure7-6-end            paper-figure-7.json   Fill   3
shot fig11-a                  invalid/fig11-a-sag-start.json Forbidden 1
shot fig11-b                  invalid/fig11-b-ceiling.json   Forbidden 1
# "Why does my face fail?": the face as it opens, then its error view (the E key).
viewer polygons/tutorial/crossing-face.json --screenshot docs/img/why-fails-open.png --size 900x600
viewer polygons/tutorial/crossing-face.json --show-error --screenshot docs/img/why-fails-error.png --size 900x600
# The same question on a dataset, as QGIS shows it: `flood check --findings` over the data,
# rendered by QGIS itself (Debian's python3-qgis; skipped without it).
if /usr/bin/python3 -c 'import qgis.core' 2>/dev/null; then
  findings=$(mktemp -d)
  "$FLOOD" check polygons/datasets/mixed.geojson --findings "$findings/problems.gpkg" -q >/dev/null || true
  /usr/bin/python3 scripts/qgis-picture.py polygons/datasets/mixed.geojson "$findings/problems.gpkg" \
    docs/img/why-fails-qgis.png 900x600 2>/dev/null
  rm -rf "$findings"
else
  echo "docs/img/why-fails-qgis.png kept: no python3-qgis (apt-get install python3-qgis qgis-providers)" >&2
fi
# Presenter mode (Tab) in the light theme, as a slide would show it.
viewer polygons/paper-figure-7.json --presenter --theme light --step "$(step_after paper-figure-7.json Bridge 2)" \
  --screenshot docs/img/presenter-light.png --size 900x600
# "Before and after": Fig. 7 step 23 (issue 27's example) in presenter view, at a projector's
# size: the names of the step's sentence labelled, NextRight's ghost at vertex 14.
viewer polygons/paper-figure-7.json --presenter --theme light --step 23 \
  --screenshot docs/img/teach-before-after.png --size 1280x800
# "Teaching with Flood": a slide (the canvas alone, light theme, with its caption), the dial
# turned to +x beside the +y run, and the whole flood of sag.json as a small animated GIF.
viewer polygons/sag.json --theme light --step "$(step_after sag.json Bridge 1)" --canvas-only --caption \
  --screenshot docs/img/teach-slide-light.png --size 900x600
viewer polygons/sag.json --theme light --up +x --step 2 --screenshot docs/img/teach-dial.png --size 1100x700
viewer polygons/sag.json --theme light --export-gif docs/img/teach-sag.gif --fps 1 --caption --size 480x320
# The whole Fig. 10 (the State table) at Fig. 7's first bridge, its cell outlined; the quiz before Fig. 7's first
# bridge, that question answered, and the answer in presenter view (the tree drawn in the window).
bridge_step=$(step_after paper-figure-7.json Bridge 1)
viewer polygons/paper-figure-7.json --state-table --step "$bridge_step" \
  --screenshot docs/img/teach-state-table.png --size 1280x800
quiz_step=$((bridge_step - 1))
viewer polygons/paper-figure-7.json --quiz bridge,spill --step "$quiz_step" \
  --screenshot docs/img/teach-quiz-question.png --size 1280x800
viewer polygons/paper-figure-7.json --quiz bridge,spill --step "$quiz_step" --answer bridge \
  --screenshot docs/img/teach-quiz-answer.png --size 1280x800
viewer polygons/paper-figure-7.json --presenter --theme light --quiz bridge,spill --step "$quiz_step" \
  --answer bridge --screenshot docs/img/teach-quiz-presenter.png --size 1280x800
echo "docs/img: $(ls docs/img/*.png | wc -l) images, $(ls docs/img/*.gif | wc -l) GIF"
