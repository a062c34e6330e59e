#!/usr/bin/env bash
# The builds for other systems that this machine can check but not run: clippy (a full type
# check and the lints) of the default build, viewer included, for Windows and for both Macs.
# Nothing links for macOS here; the check catches code and dependencies that do not build there.
# Installs the Rust targets where they are missing.
set -euo pipefail
cd "$(dirname "$0")/.."
targets=(x86_64-pc-windows-gnu aarch64-apple-darwin x86_64-apple-darwin)
installed=$(rustup target list --installed 2>/dev/null || true)
for target in "${targets[@]}"; do
  grep -qx "$target" <<<"$installed" || rustup target add "$target"
done
for target in "${targets[@]}"; do
  echo "== $target"
  start=$(date +%s)
  cargo clippy --target "$target" --lib --bins -- -D warnings
  cargo clippy --target "$target" --no-default-features --lib --bins -- -D warnings
  echo "== $target: $(( $(date +%s) - start )) s"
done
