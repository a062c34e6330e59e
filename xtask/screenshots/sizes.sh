#!/usr/bin/env bash
# Screenshots of the release viewer in a real window under Xvfb at the sizes people use it:
# 1600×900, 800×600 and 400×300 pixels, and 1600×900 at scale factor 2 (800×450 points), each on
# the embedded default scene (or on the scene given as the first argument) with fresh settings.
# A fifth shot opens the controls drawer at 400×300 (a click on "Controls" in the toolbar).
# Writes docs/window-<W>x<H>[-scale2|-drawer].png. Needs xvfb, xdotool and imagemagick (cargo xtask test
# installs them).
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release
scene=${1:-}
source xtask/lib/pictures.sh
display=":96"
for spec in "1600 900 1" "800 600 1" "400 300 1" "1600 900 2" "400 300 1 drawer"; do
  read -r width height scale drawer <<<"$spec"
  home=$(mktemp -d)
  Xvfb "$display" -screen 0 "${width}x${height}x24" -nolisten tcp >/dev/null 2>&1 &
  xvfb=$!
  sleep 1
  DISPLAY="$display" HOME="$home" XDG_DATA_HOME="$home" XDG_CONFIG_HOME="$home" \
    WINIT_X11_SCALE_FACTOR="$scale" target/release/raytracer $scene >/dev/null 2>&1 &
  viewer=$!
  # No window manager: size the window to the whole screen ourselves.
  window=$(DISPLAY="$display" xdotool search --sync --pid "$viewer" | head -n 1)
  DISPLAY="$display" xdotool windowmove "$window" 0 0 windowsize "$window" "$width" "$height"
  sleep "${SCREENSHOT_WAIT:-5}"
  suffix=$([ "$scale" = 1 ] || echo "-scale$scale")
  if [ -n "${drawer:-}" ]; then
    DISPLAY="$display" xdotool mousemove 240 12 click 1 mousemove 390 150
    sleep 2
    suffix=-drawer
  fi
  name="docs/window-${width}x${height}$suffix.png"
  import -display "$display" -window root "$name"
  record_picture "$name" "cargo xtask screenshots sizes${scene:+ $scene}" ${scene:+"file:$scene"}
  echo "wrote $name"
  kill "$viewer" 2>/dev/null || true
  wait "$viewer" 2>/dev/null || true
  kill "$xvfb" 2>/dev/null || true
  wait "$xvfb" 2>/dev/null || true
  rm -rf "$home"
done
