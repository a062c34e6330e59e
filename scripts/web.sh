#!/usr/bin/env bash
# The viewer in a browser page.
#   bash scripts/web.sh build         the static site in target/web/ (index.html, raytracer.js,
#                                     raytracer_bg.wasm): copy it to any web server
#   bash scripts/web.sh serve [PORT]  builds, then serves target/web/ on 127.0.0.1 (default port
#                                     8080) and prints the address
# Tools come from the package registries only: the wasm32 target through rustup, and
# wasm-bindgen-cli through cargo at exactly the version Cargo.lock pins for the wasm-bindgen
# crate (the two must match), installed under target/tools/.
set -euo pipefail
cd "$(dirname "$0")/.."

command=${1:-build}
site=target/web
tools=target/tools

bindgen_version() {
  awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock
}

install_tools() {
  rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown \
    || rustup target add wasm32-unknown-unknown
  local version
  version=$(bindgen_version)
  if [ -z "$version" ]; then
    echo "web.sh: Cargo.lock pins no wasm-bindgen" >&2
    exit 1
  fi
  if [ "$("$tools/bin/wasm-bindgen" --version 2>/dev/null | awk '{print $2}')" != "$version" ]; then
    echo "web.sh: installing wasm-bindgen-cli $version"
    cargo install wasm-bindgen-cli --version "$version" --root "$tools" --quiet
  fi
}

build() {
  install_tools
  cargo build --release --target wasm32-unknown-unknown --bin raytracer
  rm -rf "$site"
  mkdir -p "$site"
  "$tools/bin/wasm-bindgen" --target web --no-typescript --out-dir "$site" --out-name raytracer \
    target/wasm32-unknown-unknown/release/raytracer.wasm
  cp web/index.html "$site/"
  echo "web.sh: the site is in $site/ ($(du -k "$site/raytracer_bg.wasm" | cut -f1) KiB of wasm)"
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
  *)
    echo "usage: bash scripts/web.sh build | serve [PORT]" >&2
    exit 2
    ;;
esac
