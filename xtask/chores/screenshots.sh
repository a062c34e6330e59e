#!/usr/bin/env bash
# The pictures of the viewer in docs/, each taken from the real program.
#
# The pictures of the viewer in docs/, each from the real program (xtask/screenshots/ holds each
# one's steps and what it needs):
#   cargo xtask screenshots viewer [ARG…]   docs/screenshot.png: the release viewer on the embedded
#                                           default scene in a 1280×720 window under Xvfb (the
#                                           README's picture; ARGs go to the viewer)
#   cargo xtask screenshots readme          docs/explore.png, docs/orbit.png, docs/compare.png: the
#                                           viewer driven by egui_kittest, numbered with ImageMagick
#   cargo xtask screenshots sizes [SCENE]   docs/window-<W>x<H>….png: the window at the sizes
#                                           people use, and the controls drawer at 400×300
#   cargo xtask screenshots windows [OUT.png] [SECONDS]   docs/windows-viewer.png and
#                                           …-opened.png: the Windows viewer under Wine, before and
#                                           after opening a scene through its file dialog
#   cargo xtask screenshots                 all four
# Each picture made is written down in docs/pictures.tsv (xtask/lib/pictures.sh) with the names it
# shows; tests/pictures.rs checks them.
# Needs what `cargo xtask test` installs (Xvfb, ImageMagick, xdotool, Mesa); `windows` needs Wine
# (`cargo xtask windows install`).
set -euo pipefail
cd "$(dirname "$0")/../.."
case "${1:-all}" in
  viewer | readme | sizes | windows)
    name=$1
    shift
    bash "xtask/screenshots/$name.sh" "$@"
    ;;
  all)
    for name in viewer readme sizes windows; do
      bash "xtask/screenshots/$name.sh"
    done
    ;;
  *)
    echo "usage: cargo xtask screenshots [viewer | readme | sizes | windows] [ARG…]" >&2
    exit 2
    ;;
esac
