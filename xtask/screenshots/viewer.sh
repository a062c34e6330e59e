#!/usr/bin/env bash
# Regenerates docs/screenshot.png: the release viewer on the embedded default scene, in a
# 1280×720 window under Xvfb (needs xvfb and imagemagick; cargo xtask test installs both).
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release
display=":97"
home=$(mktemp -d)
Xvfb "$display" -screen 0 1280x720x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $viewer $xvfb 2>/dev/null || true; rm -rf "$home"' EXIT
sleep 1
DISPLAY="$display" HOME="$home" XDG_DATA_HOME="$home" XDG_CONFIG_HOME="$home" \
  target/release/raytracer "$@" >/dev/null 2>&1 &
viewer=$!
sleep "${SCREENSHOT_WAIT:-6}"
import -display "$display" -window root -crop 1280x720+0+0 docs/screenshot.png
source xtask/lib/pictures.sh
names=()
for argument in "$@"; do [ -f "$argument" ] && names+=("file:$argument"); done
record_picture docs/screenshot.png "cargo xtask screenshots viewer${*:+ $*}" "${names[@]}"
echo "wrote docs/screenshot.png"
