#!/usr/bin/env bash
# Wall time and peak memory of `render` on large canvases (issue 11): two triangles
# covering a SIDE x SIDE canvas (default 4096), rendered to `--format json` (streamed to a
# file), to `-o` (the coverage PNG) only and to `--ids-out` only; then one triangle
# covering half of the largest canvas, 16384 x 16384, to `--ids-out`. MODEL (default
# exact-snapped, `render`'s default) picks the model. Not a test: run it by hand and read
# the "Elapsed" and "Maximum resident set size" lines.
#
#   cargo build --release
#   [MODEL=fixed] benches/memory.sh [BINARY] [SIDE]   # BINARY: target/release/rasterproof
#
# Needs GNU time at /usr/bin/time. Writes its files under ${TMPDIR:-/tmp}/rp-memory.
set -euo pipefail
bin=${1:-target/release/rasterproof}
side=${2:-4096}
model=${MODEL:-exact-snapped}
dir=${TMPDIR:-/tmp}/rp-memory
mkdir -p "$dir"
full=$dir/two-triangles-$side.json
cat >"$full" <<JSON
{"width": $side, "height": $side, "triangles": [
  {"v": [[0,0],[$side,0],[$side,$side]]},
  {"v": [[0,0],[$side,$side],[0,$side]]}
]}
JSON
half=$dir/half-16384.json
cat >"$half" <<JSON
{"width": 16384, "height": 16384, "triangles": [{"v": [[0,0],[16384,0],[0,16384]]}]}
JSON
measure() {
    local label=$1 scene=$2
    shift 2
    echo "== $label: $bin render $scene --model $model $*"
    /usr/bin/time -v "$bin" render "$scene" --model "$model" "$@" 2>"$dir/time.txt" >"$dir/$label.out" || {
        cat "$dir/time.txt"
        return 1
    }
    grep -E "Elapsed \(wall clock\)|Maximum resident set size" "$dir/time.txt"
}
measure "json" "$full" --format json
measure "png" "$full" -o "$dir/x.png"
measure "ids" "$full" --ids-out "$dir/ids.png"
measure "half-16384-ids" "$half" --ids-out "$dir/half-ids.png"
