#!/usr/bin/env bash
# Regenerates the README's annotated pictures of exploring a scene, docs/explore.png and
# docs/orbit.png, and of the Compare section, docs/compare.png: the real viewer driven by egui_kittest and rendered with wgpu (Mesa's lavapipe
# where there is no GPU), then numbered with ImageMagick at the spots the example marks.
# Needs mesa-vulkan-drivers, imagemagick and fonts-dejavu-core (cargo xtask test installs them).
set -euo pipefail
cd "$(dirname "$0")/../.."
raw=$(mktemp -d)
trap 'rm -rf "$raw"' EXIT
cargo run --quiet --example screenshots -- "$raw"
source xtask/lib/pictures.sh
font=/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf
for name in explore orbit compare; do
  draw=()
  number=1
  while read -r x y; do
    # A numbered yellow badge with a dark ring, just above and left of the spot.
    bx=$((x - 14)); by=$((y - 14))
    [ "$by" -lt 14 ] && by=$((y + 14))
    draw+=(-fill '#ffd400' -stroke '#202020' -strokewidth 2
           -draw "circle $bx,$by $((bx + 11)),$by"
           -stroke none -fill '#202020' -font "$font" -pointsize 14
           -annotate "+$((bx - 4))+$((by + 5))" "$number")
    number=$((number + 1))
  done < "$raw/$name.marks"
  convert "$raw/$name.png" "${draw[@]}" "docs/$name.png"
  # The repository's files the picture shows, as the example wrote them down.
  read -r -a names < "$raw/$name.names" || true  # (one line, no newline at its end)
  record_picture "docs/$name.png" "cargo xtask screenshots readme" "${names[@]}"
  echo "wrote docs/$name.png"
done
