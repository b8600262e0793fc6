#!/bin/bash -eu
# ClusterFuzzLite / OSS-Fuzz build script: builds every fuzz target of fuzz/ with
# `cargo fuzz build -O` (the fuzz profile keeps debug assertions and overflow checks)
# and puts into $OUT, per target TARGET:
#   TARGET                    the libFuzzer binary
#   TARGET.options            its libFuzzer options (max_len; dict = TARGET.dict)
#   TARGET.dict               its dictionary, when fuzz/options/TARGET.options names one
#   TARGET_seed_corpus.zip    its committed corpus, fuzz/corpus/TARGET/ (the seed-* files and
#                             what the measured campaign kept)
#
# In the builder image $SRC, $OUT and $WORK are set and cargo fuzz builds with the
# sanitizer the job asks for (SANITIZER, address for Rust). Run outside it (fuzz/check-layout
# does), set OUT (and SRC, WORK) yourself; FUZZ_BUILD_FLAGS adds flags to
# `cargo fuzz build` (e.g. "-s none" on a stable toolchain without ASan), and
# CARGO_TARGET_DIR moves the build.
# The repository: where this script lies (.clusterfuzzlite/), or $SRC/rasterproof in the
# builder image (which runs a copy of it from $SRC).
here=$(cd "$(dirname "$0")/.." && pwd)
if [ -d "$here/fuzz/fuzz_targets" ]; then cd "$here"; else cd "$SRC/rasterproof"; fi

: "${OUT:?set OUT to the output folder}"
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
# shellcheck disable=SC2086
cargo fuzz build -O ${FUZZ_BUILD_FLAGS:-}

triple=x86_64-unknown-linux-gnu
built="${CARGO_TARGET_DIR:-fuzz/target}/$triple/release"
for source in fuzz/fuzz_targets/*.rs; do
    target=$(basename "${source%.rs}")
    cp "$built/$target" "$OUT/"
    options="fuzz/options/$target.options"
    max_len=$(sed -n 's/^max_len *= *//p' "$options")
    dict=$(sed -n 's/^dict *= *//p' "$options")
    {
        echo "[libfuzzer]"
        echo "max_len = $max_len"
        if [ -n "$dict" ]; then echo "dict = $target.dict"; fi
    } > "$OUT/$target.options"
    if [ -n "$dict" ]; then cp "fuzz/$dict" "$OUT/$target.dict"; fi
    rm -f "$OUT/${target}_seed_corpus.zip"
    if compgen -G "fuzz/corpus/$target/seed-*" > /dev/null; then
        (cd "fuzz/corpus/$target" && zip -q -j "$OUT/${target}_seed_corpus.zip" -- *)
    else
        echo "build.sh: $target has no committed seeds (fuzz/corpus/$target/seed-*)" >&2
    fi
done
