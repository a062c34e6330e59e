#!/usr/bin/env bash
# The whole test suite: installs the system packages it needs, then runs cargo test.
#   cargo xtask test [ARGUMENT…]   (ARGUMENTs go to cargo test: `cargo xtask test --test viewer`)
#
# Runs the whole test suite on a fresh Debian/Ubuntu machine: installs the system packages the
# viewer tests need (only those missing; needs root or sudo), then `cargo test` of the library
# and the tests (the program is built for them; it has no unit tests of its own). The examples
# and benchmarks are not built here (clippy --all-targets type-checks them in CI); arguments go
# to `cargo test`, and one that chooses targets (`--test viewer`, `--examples`...) replaces that
# default. The test files are gathered into a few suites (Cargo.toml's [[test]] list):
# `--test viewer viewer_files::` runs one file.
#   * xvfb, xauth, xdotool, imagemagick: the test that starts the real viewer window and takes a
#     screenshot (tests/window_screenshot.rs)
#   * mesa-vulkan-drivers, libvulkan1, libgl1-mesa-dri, libegl1: software GPU (lavapipe/llvmpipe)
#     for the window and for egui_kittest's wgpu rendering
#   * libxkbcommon-x11-0, libx11-xcb1, libxcursor1, libxrandr2, libxi6: what winit loads under X11
#   * fonts-dejavu-core: a font for the screenshot's window decorations (none are drawn by Xvfb), and
#     Arabic; fonts-wqy-microhei: Chinese, Japanese and Korean (tests/window_text.rs: the viewer
#     draws text in other scripts from the system's fonts)
set -euo pipefail
cd "$(dirname "$0")/../.."

packages=(xvfb xauth xdotool imagemagick strace mesa-vulkan-drivers libvulkan1 libgl1-mesa-dri libegl1
          libxkbcommon-x11-0 libx11-xcb1 libxcursor1 libxrandr2 libxi6 fonts-dejavu-core fonts-wqy-microhei)
source xtask/lib/apt.sh
apt_install_missing "${packages[@]}"

# The default selection, unless the arguments choose targets themselves.
selected=no
for argument in "$@"; do
  case "$argument" in
    --) break ;;
    --lib | --bin | --bin=* | --bins | --test | --test=* | --tests | --example | --example=* \
      | --examples | --bench | --bench=* | --benches | --all-targets | --doc) selected=yes ;;
  esac
done
[ "$selected" = yes ] || set -- --lib --tests "$@"
cargo test "$@"
