#!/usr/bin/env bash
# The paper's open conjecture (§6: "we triangulate both the polygon and its complement, for
# verification purposes. We leave as an open conjecture that this detects all invalid or
# degenerate polygons"), measured. For every invalid input the project has — polygons/invalid,
# polygons/regress and the hand-made degenerate cases of polygons/conjecture/probes (files
# validate() refuses; malformed files are not polygons), the
# generator's invalid families (flood generate, several seeds and sizes), and the GeoJSON/WKT
# files of any DIR given, and a GEOS-differential corpus (scripts/geos-diff.sh --dump: every
# generated polygon or MultiPolygon GEOS calls invalid, --geos N cases, default 2000, 0 for none)
# — runs `flood verify --no-validate` and records what caught it: the
# forbidden transitions of the polygon's flood, only the complement's flood, only the exact
# checker, or nothing (it slips through). The smallest slipping input of each source is shrunk
# (`flood shrink --slipping`) into polygons/conjecture/. Prints the markdown table and replaces
# the block between the conjecture markers in docs/ALGORITHM.md.
#
# Usage: scripts/conjecture.sh [--no-shrink] [--no-docs] [--geos N] [DIR...]   (build first; FLOOD=path)
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
flood=${FLOOD:-$root/build/flood}
shrink=1 docs=1 geos=2000 dirs=()
while [ $# -gt 0 ]; do
    case "$1" in
        --no-shrink) shrink=0 ;;
        --no-docs) docs=0 ;;
        --geos) geos=${2:-}; shift; [[ "$geos" =~ ^[0-9]+$ ]] || { echo "$0: --geos needs a count" >&2; exit 2; } ;;
        -*) echo "usage: $0 [--no-shrink] [--no-docs] [--geos N] [DIR...]" >&2; exit 2 ;;
        *) [ -d "$1" ] || { echo "$0: $1: not a directory" >&2; exit 2; }; dirs+=("$1") ;;
    esac
    shift
done
[ -x "$flood" ] || { echo "$0: $flood not found: cmake --build build first (or set FLOOD)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
results=$tmp/results.tsv  # source, input, verdict, vertex count
geosDir=""
if [ "$geos" -gt 0 ]; then
    geosDir=$tmp/geos-differential
    "$root/scripts/geos-diff.sh" --seed 1 --cases "$geos" --dump "$geosDir" >/dev/null ||
        { echo "$0: scripts/geos-diff.sh failed (libgeos-dev installed? scripts/install-deps.sh)" >&2; exit 1; }
fi
: >"$results"
sizes="30 300 3000" seeds="1 2 3 4"

# measure SOURCE FILE NAME: appends one row for an invalid input; skips valid and malformed ones.
measure() {
    local source=$1 file=$2 name=$3 out rc verdict vertices
    "$flood" verify "$file" >/dev/null 2>&1
    rc=$?
    if [ $rc -ne 4 ]; then  # 0 valid, 3 malformed, 7 verification failed on valid input
        echo "$source	$name	skipped-$rc	0" >>"$results"
        return
    fi
    out=$(timeout 60 "$flood" verify --no-validate "$file" 2>&1)
    rc=$?
    case $rc in
        0) verdict=nothing ;;
        124) verdict=hang ;;
        7) verdict=$(sed -n 's/^verify: FAILED (caught by: \(.*\))$/\1/p' <<<"$out") ;;
        *) verdict=crash ;;
    esac
    vertices=$(sed -n 's/^verify: ok: \([0-9]*\) vertices.*/\1/p' <<<"$out")
    echo "$source	$name	${verdict:-crash}	${vertices:-0}" >>"$results"
    [ "$verdict" = nothing ] && cp "$file" "$tmp/slip-$(echo "$source-$name" | tr '/ ' '__')"
}

for f in "$root"/polygons/invalid/* "$root"/polygons/regress/* "$root"/polygons/conjecture/probes/*; do
    case "$f" in *.json | *.wkt) measure "$(dirname "${f#"$root"/}")" "$f" "$(basename "$f")" ;; esac
done
# The invalid families, as listed by flood generate's unknown-family message.
families=$("$flood" generate '?' 3 2>&1 | sed -n 's/.*invalid families (validate() refuses them)://p')
[ -n "$families" ] || { echo "$0: flood generate lists no invalid families" >&2; exit 1; }
for family in $families; do
    # Random rings are cheap and each seed a new shape: many more of them.
    fseeds=$seeds
    [ "$family" = random-lattice ] && fseeds=$(seq 1 100)
    for size in $sizes; do
        for seed in $fseeds; do
            g=$tmp/g.json
            "$flood" generate "$family" "$size" --seed "$seed" -o "$g" || exit 1
            measure "generated $family" "$g" "$family $size --seed $seed"
        done
    done
done
for d in "${dirs[@]}" ${geosDir:+"$geosDir"}; do
    for f in "$d"/*.json "$d"/*.geojson "$d"/*.wkt; do
        [ -f "$f" ] && measure "$(basename "$d")" "$f" "$(basename "$f")"
    done
done

# The table: one row per source, then the total.
table=$(awk -F'\t' '
    $3 ~ /^skipped/ { skipped[$1]++; next }
    { if (!($1 in n)) order[++rows] = $1; n[$1]++; c[$1, $3]++; N++; C[$3]++ }
    END {
        print "| invalid inputs | count | polygon'"'"'s flood | only the complement | only the checker | nothing (slips) | crash or hang |"
        print "|---|---|---|---|---|---|---|"
        for (i = 1; i <= rows; i++) {
            s = order[i]
            printf "| %s | %d | %d | %d | %d | %d | %d |\n", s, n[s], c[s, "polygon"], c[s, "complement"], c[s, "checker"], c[s, "nothing"], c[s, "crash"] + c[s, "hang"]
        }
        printf "| **all** | **%d** | **%d** | **%d** | **%d** | **%d** | **%d** |\n", N, C["polygon"], C["complement"], C["checker"], C["nothing"], C["crash"] + C["hang"]
    }' "$results")
slips=$(awk -F'\t' '$3 == "nothing" { if (!($1 in n)) order[++k] = $1; n[$1]++ }
    END { for (i = 1; i <= k; i++) printf "%s%s (%d)", (i > 1 ? ", " : ""), order[i], n[order[i]]; if (!k) printf "none" }' "$results")
skipped=$(awk -F'\t' '$3 ~ /^skipped/ { k++ } END { print k + 0 }' "$results")

# The smallest slipping input of each source, shrunk.
examples=""
if [ $shrink -eq 1 ]; then
    mkdir -p "$root/polygons/conjecture"
    while IFS=$'\t' read -r source name; do
        src=$tmp/slip-$(echo "$source-$name" | tr '/ ' '__')
        dest=polygons/conjecture/$(echo "${source#generated }" | tr ' /' '--').json
        if "$flood" shrink --slipping "$src" -o "$root/$dest" 2>"$tmp/shrink.log"; then
            examples+="- \`$dest\`: shrunk from $source \`$name\` ($(sed -n 's/^shrink: [^:]*: \(.*\) (.*/\1/p' "$tmp/shrink.log" | head -1))"$'\n'
        fi
    done < <(awk -F'\t' '$3 == "nothing" && (!($1 in best) || $4 + 0 < v[$1]) { best[$1] = $2; v[$1] = $4 + 0 }
                         END { for (s in best) print s "\t" best[s] }' "$results" | sort)
fi

block="Measured by \`scripts/conjecture.sh${dirs[*]:+ ${dirs[*]}}\` ($(date -u +%Y-%m-%d)):
\`flood verify --no-validate\` on every input that \`validate()\` refuses; generated families
at sizes $sizes, seeds $seeds (random-lattice: seeds 1 to 100); geos-differential: the cases
GEOS 3.11 calls invalid among \`scripts/geos-diff.sh --seed 1 --cases $geos\`; $skipped files skipped
(malformed, or valid once written and read back). Each input is counted once, by the first
check that caught it.

$table

Slipping through all: $slips.
${examples:+
Shrunk examples (\`flood shrink --slipping\`):
$examples}"
printf '%s\n' "$block"
if [ $docs -eq 1 ]; then
    doc=$root/docs/ALGORITHM.md
    grep -q '<!-- conjecture:begin -->' "$doc" || { echo "$0: no conjecture markers in $doc" >&2; exit 1; }
    BLOCK="$block" python3 - "$doc" <<'PY'
import os, re, sys
path = sys.argv[1]
text = open(path).read()
new = "<!-- conjecture:begin -->\n" + os.environ["BLOCK"].rstrip() + "\n<!-- conjecture:end -->"
text = re.sub(r"<!-- conjecture:begin -->.*?<!-- conjecture:end -->", lambda m: new, text, flags=re.S)
open(path, "w").write(text)
PY
fi
