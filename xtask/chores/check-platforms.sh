#!/usr/bin/env bash
# Clippy for the builds this machine cannot run: Windows and the Mac.
#   cargo xtask check-platforms [macos | all]   (no argument: Windows GNU and the Mac)
#
# The builds for other systems that this machine can check but not run: clippy (a full type
# check and the lints) of the default build, viewer included, and of the headless one, for
# Windows (the GNU toolchain that the Windows download and CI's Wine tests use) and for the Mac
# (Apple silicon). Nothing links for macOS here; the check catches code and dependencies that do
# not build there. The code has no switch on the processor or on Windows' C runtime, so Intel Macs
# and MSVC build what these two do: CI leaves them out to stay within its time, and
# `cargo xtask check-platforms all` checks them as well; `macos` checks the Mac alone (CI). Tests, benchmarks and examples are not checked for macOS: criterion,
# a dependency of all of them, compiles C (alloca) for the target, which nothing here can.
# Installs the Rust targets, and mingw-w64 (mimalloc's C for the GNU Windows build), where they
# are missing.
set -euo pipefail
cd "$(dirname "$0")/../.."
source xtask/lib/apt.sh
# target, then the features of its viewer build ("default": the default features)
checks=(
  "x86_64-pc-windows-gnu default"
  "aarch64-apple-darwin default"
)
case "${1:-}" in
  all) checks+=("x86_64-pc-windows-msvc gui" "x86_64-apple-darwin default") ;;
  # What CI runs: it builds the Windows program in full and runs it under Wine (cargo xtask windows
  # test, cargo xtask release test), which leaves the Mac to this check.
  macos) checks=("aarch64-apple-darwin default") ;;
  "") ;;
  *) echo "usage: cargo xtask check-platforms [macos | all]" >&2; exit 2 ;;
esac
# mingw-w64 only for a Windows check (the Mac's alone, as CI runs it, installs no package).
if [[ "${checks[*]}" == *windows* ]] && ! command -v x86_64-w64-mingw32-gcc >/dev/null; then
  apt_install gcc-mingw-w64-x86-64
fi
installed=$(rustup target list --installed 2>/dev/null || true)
for check in "${checks[@]}"; do
  read -r target features <<<"$check"
  grep -qx "$target" <<<"$installed" || rustup target add "$target"
  echo "== $target"
  start=$SECONDS
  if [ "$features" = default ]; then
    cargo clippy --target "$target" --lib --bins -- -D warnings
  else
    cargo clippy --target "$target" --no-default-features --features "$features" --lib --bins -- -D warnings
  fi
  cargo clippy --target "$target" --no-default-features --lib --bins -- -D warnings
  echo "== $target: $(( SECONDS - start )) s"
done
