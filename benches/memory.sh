#!/usr/bin/env bash
# Wall time and peak memory of `render` on a large, fully covered canvas (issue 11, part
# 6): two triangles covering a SIDE x SIDE canvas (default 4096), rendered with the
# `fixed` model to `--format json` (streamed to a file), to `-o` (the coverage PNG) only,
# and to `--ids-out` only. Not a test: run it by hand and read the "Elapsed" and "Maximum
# resident set size" lines.
#
#   cargo build --release
#   benches/memory.sh [BINARY] [SIDE]     # BINARY defaults to target/release/rasterproof
#
# Needs GNU time at /usr/bin/time. Writes its files under ${TMPDIR:-/tmp}/rp-memory.
set -euo pipefail
bin=${1:-target/release/rasterproof}
side=${2:-4096}
dir=${TMPDIR:-/tmp}/rp-memory
mkdir -p "$dir"
scene=$dir/two-triangles-$side.json
cat >"$scene" <<JSON
{"width": $side, "height": $side, "triangles": [
  {"v": [[0,0],[$side,0],[$side,$side]]},
  {"v": [[0,0],[$side,$side],[0,$side]]}
]}
JSON
measure() {
    local label=$1
    shift
    echo "== $label: $bin render $scene --model fixed $*"
    /usr/bin/time -v "$bin" render "$scene" --model fixed "$@" 2>"$dir/time.txt" >"$dir/$label.out" || {
        cat "$dir/time.txt"
        return 1
    }
    grep -E "Elapsed \(wall clock\)|Maximum resident set size" "$dir/time.txt"
}
measure "json" --format json
measure "png" -o "$dir/x.png"
if "$bin" render --help | grep -q -- --ids-out; then
    measure "ids" --ids-out "$dir/ids.png"
fi
