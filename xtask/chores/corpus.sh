#!/usr/bin/env bash
# The diagnosis on the real programs' images (tests/corpus.rs), on the program the download ships.
#   cargo xtask corpus [ARGUMENT…]   (ARGUMENTs go to the test binary: `cargo xtask corpus range`)
#
# Builds the program in the `dist` profile (nothing to do where `cargo xtask release build` has
# just built it, as in CI, with RAYTRACER_DIST_TARGETS naming the same targets: xtask/lib/dist.sh), then runs every test of tests/corpus.rs against it, the two that
# compare every image of every program included: a plain `cargo test` (the README's test
# command) leaves those two out, for they diagnose some 600 images one after another and take
# minutes on the debug build. Then the diagnosis suite's sweeps that the README's test command
# samples (tests/compare.rs: every course scene's images against every other's;
# tests/course_mistakes.rs: each mistake on every course scene; tests/generated.rs: 60 programs,
# not 20). Run it after a change to the comparison or the diagnosis; CI runs it on every change.
set -euo pipefail
cd "$(dirname "$0")/../.."

host=$(rustc -vV | sed -n 's/^host: //p')
source xtask/lib/dist.sh
dist_build "$host"
RAYTRACER_CORPUS_BIN="$PWD/target/$host/dist/raytracer" cargo test --test corpus -- --include-ignored "$@"
[ $# -gt 0 ] || cargo test --test diagnosis -- --ignored
