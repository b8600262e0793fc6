#!/usr/bin/env bash
# Wall time and peak memory of `render` on large canvases (issue 11) and whole frames of
# small triangles and a whole frame on threads (issue 31, at the end): two triangles
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

# Whole frames of small triangles (issue 31): N triangles of 3-decimal coordinates, each
# within 4 px of a random point of a 1024 x 1024 canvas, rendered by `fixed` to
# `--ids-out` (the figures of `cargo bench --features bench --bench pipeline`, with the peak memory).
# SMALL (default "100000 1000000") picks the sizes.
for n in ${SMALL:-100000 1000000}; do
    small=$dir/small-$n.json
    awk -v n="$n" 'BEGIN {
        srand(7); printf "{\"width\":1024,\"height\":1024,\"triangles\":[";
        for (k = 0; k < n; k++) {
            x = int(rand() * 1020000); y = int(rand() * 1020000);
            printf "%s{\"v\":[", (k ? "," : "");
            for (i = 0; i < 3; i++) {
                vx = x + int(rand() * 4000); vy = y + int(rand() * 4000);
                printf "%s[%d.%03d,%d.%03d]", (i ? "," : ""), vx / 1000, vx % 1000, vy / 1000, vy % 1000;
            }
            printf "]}";
        }
        printf "]}\n";
    }' >"$small"
    model=fixed measure "small-$n-ids" "$small" --ids-out "$dir/small-ids.png"
done

# The whole frame (issue 31): a 16384 x 16384 mesh of 2 x 708^2 triangles (a grid of cells
# cut along a diagonal, 1/1000 px vertices, the mesh of `cargo bench --features bench --bench pipeline`),
# `render --model fixed` writing only its summary, on 1 and 2 threads (the frame counted
# band by band: a few bands of coverage held at a time, not the 1 GiB canvas). FRAME=0
# skips it.
if [ "${FRAME:-1}" != 0 ]; then
    mesh=$dir/mesh-16384.json
    awk 'BEGIN {
        side = 16384; cells = 708;
        printf "{\"width\":%d,\"height\":%d,\"triangles\":[", side, side;
        for (i = 0; i <= cells; i++) {
            t = int(i * side * 1000 / cells);
            at[i] = sprintf("%d.%03d", int(t / 1000), t % 1000);
        }
        first = 1;
        for (j = 0; j < cells; j++) {
            for (i = 0; i < cells; i++) {
                x0 = at[i]; x1 = at[i + 1]; y0 = at[j]; y1 = at[j + 1];
                printf "%s{\"v\":[[%s,%s],[%s,%s],[%s,%s]]}", (first ? "" : ","), x0, y0, x1, y0, x1, y1;
                printf ",{\"v\":[[%s,%s],[%s,%s],[%s,%s]]}", x0, y0, x1, y1, x0, y1;
                first = 0;
            }
        }
        printf "]}\n";
    }' >"$mesh"
    for jobs in 1 2; do
        model=fixed measure "frame-jobs-$jobs" "$mesh" --jobs "$jobs"
    done
fi
