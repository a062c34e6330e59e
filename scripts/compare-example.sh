#!/usr/bin/env bash
# The README's comparison example: a ray caster with tmin = 0 renders scenes/scene1_07.txt (the
# project's variant renderer stands in for it), then the release binary compares its images with
# the exact ones. Writes docs/compare-diff.png (the -diff picture) and docs/compare-diff.txt (the
# command and what it printed, with its exit status).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --example mistakes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
target/release/examples/mistakes make tmin-zero scenes/scene1_07.txt 200 200 -2 2 \
  "$work/mine.tga" "$work/mine_depth.tga"
command=(target/release/raytracer -input scenes/scene1_07.txt -compare_output "$work/mine.tga"
         -compare_depth -2 2 "$work/mine_depth.tga" -diff docs/compare-diff.png)
status=0
output=$("${command[@]}") || status=$?
{
  echo "\$ raytracer -input scenes/scene1_07.txt -compare_output mine.tga -compare_depth -2 2 mine_depth.tga -diff diff.png"
  echo "$output"
  echo "(exit status $status)"
} > docs/compare-diff.txt
cat docs/compare-diff.txt
