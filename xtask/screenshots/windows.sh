#!/usr/bin/env bash
# The Windows viewer under Wine, in a real window under Xvfb: builds the whole program for
# x86_64-pc-windows-gnu (cargo xtask windows viewer), starts it on the embedded default scene,
# waits, and takes a screenshot of the screen (OUT.png); then clicks Open…, types the path of
# a copy of scenes/scene1_02.txt (C:\scenes\ in Wine's prefix) into the Windows file dialog,
# presses Enter and takes another (OUT-opened.png).
#   cargo xtask screenshots windows [OUT.png] [SECONDS]   (default docs/windows-viewer.png, 25)
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${1:-docs/windows-viewer.png}"
wait_s="${2:-25}"
cargo xtask windows viewer >/dev/null
source xtask/lib/apt.sh
apt_install_missing xvfb imagemagick xdotool
export WINEPREFIX="$PWD/target/wine-prefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
[ -f "$WINEPREFIX/system.reg" ] || { wineboot -i >/dev/null 2>&1 || true; wineserver -w; }
rm -f "$WINEPREFIX/display"
Xvfb -displayfd 1 -screen 0 1280x800x24 > "$WINEPREFIX/display" 2>/dev/null &
xvfb=$!
trap 'wineserver -k 2>/dev/null || true; kill "$xvfb" 2>/dev/null || true' EXIT
for _ in $(seq 100); do [ -s "$WINEPREFIX/display" ] && break; sleep 0.1; done
[ -s "$WINEPREFIX/display" ] || { echo "Xvfb did not start" >&2; exit 1; }
export DISPLAY=":$(cat "$WINEPREFIX/display")"
wine target/x86_64-pc-windows-gnu/release/raytracer.exe > "$WINEPREFIX/viewer.log" 2>&1 &
sleep "$wait_s"
import -window root "$out"
# The toolbar's first button, Open…, at the window's top left (no window manager places it).
xdotool mousemove 42 35 click 1
sleep 8
mkdir -p "$WINEPREFIX/drive_c/scenes"
cp scenes/scene1_02.txt "$WINEPREFIX/drive_c/scenes/"
xdotool type --delay 20 'C:\scenes\scene1_02.txt'
xdotool key Return
sleep 8
import -window root "${out%.png}-opened.png"
if [ "$out" = docs/windows-viewer.png ]; then
  source xtask/lib/pictures.sh
  record_picture "$out" "cargo xtask screenshots windows"
  record_picture "${out%.png}-opened.png" "cargo xtask screenshots windows" file:scenes/scene1_02.txt
fi
echo "screenshots: $out ${out%.png}-opened.png (the viewer said: $(tr '\n' ' ' < "$WINEPREFIX/viewer.log"))"
