#!/usr/bin/env bash
# The viewer as a web page: build, serve, test in headless Chromium, measure.
#   cargo xtask web build         the static site in target/web/ (index.html, raytracer.js,
#                                 raytracer_bg.wasm, scenes/ with the course scenes): copy it
#                                 to any web server
#   cargo xtask web serve [PORT]  builds, then serves target/web/ on 127.0.0.1 (default port
#                                 8080) and prints the address
#   cargo xtask web test          builds, runs tests/same_pixels.rs in WebAssembly under Node
#                                 (wasm-bindgen-test), then the browser tests (tests/web/) in Debian's
#                                 headless chromium, driven by playwright-core from npm
#                                 (installs chromium with apt and the npm package when missing)
#   cargo xtask web report        builds, then measures the page against the native binary:
#                                 docs/web.md and docs/web-page.png (tests/web/report.mjs)
# Tools come from the package registries only: the wasm32 target through rustup, and
# wasm-bindgen-cli through cargo at exactly the version Cargo.lock pins for the wasm-bindgen
# crate (the two must match), installed under target/tools/.
# With RAYTRACER_WEB_CLIPPY=1 (CI sets it), the page's build is linted by clippy as it compiles,
# warnings denied: clippy-driver compiles this package in rustc's place, as `cargo clippy` runs
# it, so the lints of `cargo clippy --target wasm32-unknown-unknown --lib --bins -- -D warnings`
# cost no second pass over the dependencies (CI's separate step took 76 s).
set -euo pipefail
cd "$(dirname "$0")/../.."
source xtask/lib/apt.sh

command=${1:-build}
site=target/web
tools=target/tools

bindgen_version() {
  awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock
}

# The wasm32 target, where missing.
install_target() {
  rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown \
    || rustup target add wasm32-unknown-unknown
}

# Installs wasm-bindgen-cli at the version Cargo.lock pins, where target/tools/ lacks it.
install_bindgen() {
  local version
  version=$(bindgen_version)
  if [ -z "$version" ]; then
    echo "web.sh: Cargo.lock pins no wasm-bindgen" >&2
    exit 1
  fi
  if [ "$("$tools/bin/wasm-bindgen" --version 2>/dev/null | awk '{print $2}')" != "$version" ]; then
    echo "web.sh: installing wasm-bindgen-cli $version"
    # --force: cargo skips a version it has recorded as installed, even with its program gone.
    # At opt-level 1 the tool builds in less time and writes the same bytes (the page's wasm and
    # JavaScript compared, both builds run once on the same wasm); it binds one file per build.
    CARGO_PROFILE_RELEASE_OPT_LEVEL=1 \
      cargo install wasm-bindgen-cli --version "$version" --root "$tools" --quiet --force
  fi
}

# The page: the program built for wasm32 while wasm-bindgen-cli is installed beside it, then
# bound by it. The install runs at the lowest priority: it takes the core the program's build
# leaves idle (its last unit compiles on one) and slows it no more than that. At equal priority, in
# CI's fresh build (every crate compiled, both cores busy), the two together took 6m 04s, the
# program alone 3m 08s after the install's 2 min or so.
build() {
  install_target
  (renice -n 19 -p "$BASHPID" >/dev/null && install_bindgen) &
  local installing=$!
  local lint=()
  if [ "${RAYTRACER_WEB_CLIPPY:-}" = 1 ]; then
    rustup component add clippy >/dev/null 2>&1 || true
    lint=(env "RUSTC_WORKSPACE_WRAPPER=$(rustup which clippy-driver)"
      "CLIPPY_ARGS=-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__")
  fi
  if ! "${lint[@]}" cargo build --release --target wasm32-unknown-unknown --bin raytracer; then
    kill "$installing" 2>/dev/null || true
    exit 1
  fi
  wait "$installing"
  rm -rf "$site"
  mkdir -p "$site"
  "$tools/bin/wasm-bindgen" --target web --no-typescript --out-dir "$site" --out-name raytracer \
    target/wasm32-unknown-unknown/release/raytracer.wasm
  cp web/index.html "$site/"
  mkdir -p "$site/scenes"
  cp scenes/*.txt "$site/scenes/"
  echo "web.sh: the site is in $site/ ($(du -k "$site/raytracer_bg.wasm" | cut -f1) KiB of wasm)"
}

browser_tools() {
  local missing=()
  command -v chromium >/dev/null 2>&1 || missing+=(chromium)
  command -v node >/dev/null 2>&1 || missing+=(nodejs)
  command -v npm >/dev/null 2>&1 || missing+=(npm)
  command -v convert >/dev/null 2>&1 || missing+=(imagemagick)
  # A CJK font for the browser: the page draws a character egui's fonts lack with the browser's
  # fonts (tests/web: a scene named in other scripts).
  [ -e /usr/share/fonts/truetype/wqy/wqy-microhei.ttc ] || missing+=(fonts-wqy-microhei)
  apt_install "${missing[@]}"
  (cd tests/web && npm ci --no-audit --no-fund --silent)
}

# The native binary (the tests' oracle) and a dense scene of 100,000 spheres. The test takes the
# debug build (its pixels are the release build's; CI has just built its dependencies for the
# test suite), the report the release build, whose frame times it prints.
native_tools() {
  local profile=$1
  if [ "$profile" = release ]; then
    cargo build --release --bin raytracer --example generate --example viewer_frame
  else
    cargo build --bin raytracer --example generate
  fi
  mkdir -p target/web-test
  [ -f target/web-test/dense_1e5.txt ] \
    || "target/$profile/examples/generate" --dense 100000 target/web-test/dense_1e5.txt
}

case "$command" in
  build)
    build
    ;;
  serve)
    build
    port=${2:-8080}
    echo "web.sh: serving $site on http://127.0.0.1:$port/ (Ctrl-C stops)"
    exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site"
    ;;
  test)
    # Chromium, Node and the browser driver are installed while the page builds: downloads and
    # unpacking, which take little of the cores the build keeps busy.
    browser_tools &
    browser_tools_installing=$!
    build
    echo "web.sh: the page built at ${SECONDS} s"
    # The renderer in WebAssembly under Node: the native frames, bit for bit (tests/same_pixels.rs).
    # The renderer needs no viewer: built without it, the test leaves egui's stack unbuilt.
    CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER="$PWD/$tools/bin/wasm-bindgen-test-runner" \
      cargo test --target wasm32-unknown-unknown --no-default-features --test same_pixels
    echo "web.sh: the WebAssembly test passed at ${SECONDS} s"
    wait "$browser_tools_installing"
    native_tools debug
    echo "web.sh: the browser tests start at ${SECONDS} s"
    RAYTRACER_WEB_SITE=target/web RAYTRACER_BIN=target/debug/raytracer \
      RAYTRACER_SCENES=scenes RAYTRACER_DENSE_SCENE=target/web-test/dense_1e5.txt \
      RAYTRACER_CHROMIUM="$(command -v chromium)" \
      node --test --test-concurrency=1 tests/web/
    ;;
  report)
    build
    browser_tools
    native_tools release
    RAYTRACER_WEB_SITE=target/web RAYTRACER_SCENES=scenes \
      RAYTRACER_DENSE_SCENE=target/web-test/dense_1e5.txt \
      RAYTRACER_CHROMIUM="$(command -v chromium)" \
      node tests/web/report.mjs docs/web.md docs/web-page.png
    # The page's picture is of the default scene, which is embedded: no file's name.
    source xtask/lib/pictures.sh
    record_picture docs/web-page.png "cargo xtask web report"
    ;;
  *)
    echo "usage: cargo xtask web build | serve [PORT] | test | report" >&2
    exit 2
    ;;
esac
