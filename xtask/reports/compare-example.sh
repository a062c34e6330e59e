#!/usr/bin/env bash
# The README's comparison example: the release binary compares one real student program's images
# of scene1_05 (tests/corpus/moonlightcc: its camera vectors are not unit and not perpendicular to
# the direction, and it normalises depth per image) with the exact ones. Writes
# docs/compare-diff.png (the -diff picture), docs/compare-diff.txt (the command and what it
# printed, with its exit status) and docs/compare-diff.json (the same answer with
# -compare_format json).
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release
theirs=tests/corpus/moonlightcc
rm -f docs/compare-diff.png
command=(target/release/raytracer -input scenes/scene1_05.txt
         -compare_output "$theirs/output1_05.png"
         -compare_depth 14.5 19.5 "$theirs/depth1_05.png" -diff docs/compare-diff.png)
status=0
output=$("${command[@]}") || status=$?
{
  echo "\$ raytracer -input scene1_05.txt -compare_output mine.tga -compare_depth 14.5 19.5 mine_depth.tga -diff diff.png"
  echo "$output"
  echo "(exit status $status)"
} > docs/compare-diff.txt
status=0
"${command[@]:0:${#command[@]}-2}" -compare_format json > docs/compare-diff.json || status=$?
[ "$status" -eq 3 ] || { echo "the JSON answer ended with status $status" >&2; exit 1; }
# The -diff picture's words are its panels' titles and counts: no file's name.
source xtask/lib/pictures.sh
record_picture docs/compare-diff.png "cargo xtask report compare-diff"
cat docs/compare-diff.txt
