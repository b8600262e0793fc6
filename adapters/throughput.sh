#!/bin/sh
# Scenes per second of `rasterproof hunt` against each adapter, once per scene (--cmd)
# and kept alive (--serve), in one run: 16x16 canvases, 2 jobs, no shrinking (the scene
# loop alone: generate, render, judge), f32-exact coordinates. Prints a Markdown table.
#   sh adapters/throughput.sh [TINY_SKIA_CASES] [MESA_CASES]
set -e
cd "$(dirname "$0")/.."
cargo build --release --quiet && cargo build --release --quiet --example tiny-skia-adapter
R=target/release/rasterproof
T=target/release/examples/tiny-skia-adapter
PY=${RASTERPROOF_ADAPTER_PYTHON:-/usr/bin/python3}
TS=${1:-2000}
MS=${2:-200}
row() { # NAME CASES ARGS... -- PER_SCENE_CMD -- SERVE_CMD
    name=$1; cases=$2; shift 2
    args=""; while [ "$1" != "--" ]; do args="$args $1"; shift; done; shift
    per=$1; serve=$3
    out=""
    for how in cmd serve; do
        if [ $how = cmd ]; then c=$per; else c=$serve; fi
        start=$(date +%s.%N)
        $R hunt --$how "$c" $args --float32-exact --cases "$cases" --jobs 2 --shrink-runs 0 --quiet > /tmp/rasterproof-throughput.txt || true
        end=$(date +%s.%N)
        starts=$(sed -n 's/^renderer: .* asked for, \([0-9]*\) program start.*/\1/p' /tmp/rasterproof-throughput.txt)
        rate=$(echo "$cases / ($end - $start)" | bc -l)
        out="$out | $(printf '%.0f' "$rate") scenes/s ($starts starts)"
        eval "rate_$how=$rate"
    done
    echo "| $name | $cases$out | $(printf '%.1f' "$(echo "$rate_serve / $rate_cmd" | bc -l)")x |"
}
echo "| adapter | scenes | once per scene (--cmd) | kept alive (--serve) | speed-up |"
echo "|---|---|---|---|---|"
row tiny-skia "$TS" --preset gl --subpixel-bits 6 --rounding towards-zero -- "$T {scene} {out}" -- "$T --serve"
row llvmpipe "$MS" --preset gl -- "$PY adapters/osmesa/render.py {scene} {out} --driver llvmpipe" -- "$PY adapters/osmesa/render.py --serve --driver llvmpipe"
row softpipe "$MS" --preset gl --model exact -- "$PY adapters/osmesa/render.py {scene} {out} --driver softpipe" -- "$PY adapters/osmesa/render.py --serve --driver softpipe"
