#!/usr/bin/env bash
# The Windows build, checked under Wine on Linux.
# Debian's mingw-w64 and wine64 build and run it.
#   cargo xtask windows install the Rust target, mingw-w64 and Wine, where missing
#   cargo xtask windows build   the command line's release .exe for x86_64-pc-windows-gnu
#                               (without the viewer) and the test scaffolding beside it
#   cargo xtask windows test    the program the Windows download ships (viewer included,
#                               the `dist` profile), then tests/windows_exe.rs against it
#                               under Wine (what CI runs)
#   cargo xtask windows unit    build, then the library's unit tests built for Windows, under
#                               Wine. Not in CI: their build compiles every test dependency
#                               (the viewer's test stack included) for Windows, more than CI's
#                               time allows; the platform code they test is met at the
#                               boundary by tests/windows_exe.rs
#   cargo xtask windows viewer  the whole program (viewer included) for Windows
# Installs what is missing (the Rust target, mingw-w64, wine64; needs root or sudo).
# The scaffolding (tests/windows/*.c) is never shipped: bcryptprimitives.dll stands in for the
# one Wine 8 lacks (Rust's standard library calls its ProcessPrng at start-up), hold_open.exe
# holds a file open as another Windows program would.
set -euo pipefail
cd "$(dirname "$0")/../.."
source xtask/lib/apt.sh
source xtask/lib/dist.sh

target=x86_64-pc-windows-gnu
out="target/$target/release"

install() {
  local installed
  installed=$(rustup target list --installed 2>/dev/null || true)
  grep -qx "$target" <<<"$installed" || rustup target add "$target"
  apt_install_missing gcc-mingw-w64-x86-64 wine64 wine
}

scaffolding() {
  x86_64-w64-mingw32-gcc -O2 -shared -o "$out/bcryptprimitives.dll" tests/windows/processprng.c -ladvapi32
  x86_64-w64-mingw32-gcc -O2 -o "$out/hold_open.exe" tests/windows/hold_open.c
}

wine_prefix() {
  # A prefix of our own, made once; no Mono or Gecko installer prompts.
  export WINEPREFIX="$PWD/target/wine-prefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
  if [ ! -f "$WINEPREFIX/system.reg" ]; then
    wineboot -i >/dev/null 2>&1 || true
    wineserver -w
  fi
}

case "${1:-}" in
  install)
    install
    ;;
  build)
    install
    cargo build --release --target "$target" --no-default-features --features mimalloc
    scaffolding
    ls -l "$out/raytracer.exe"
    ;;
  test)
    install
    # The program the Windows download ships (viewer included, the `dist` profile): the release
    # archive (cargo xtask release windows) takes this build as it is.
    dist_build "$target"
    out="target/$target/dist"
    scaffolding
    wine_prefix
    # One server for the whole run (each test starts several programs), stopped at the end.
    wineserver -p 300 2>/dev/null || true  # (already running: fine)
    trap 'wineserver -k 2>/dev/null || true' EXIT
    # Wine's first program starts its services (winedevice.exe), which inherit its standard
    # output and error and keep them open: start them here, on /dev/null, so that no test's
    # pipes are held open after its program has ended (a test waiting for them would hang).
    wine "$out/raytracer.exe" -help </dev/null >/dev/null 2>&1
    RAYTRACER_WINDOWS_EXE="$PWD/$out/raytracer.exe" cargo test --test windows_exe -- --ignored
    ;;
  unit)
    install
    cargo build --release --target "$target" --no-default-features --features mimalloc
    scaffolding
    # The library's own unit tests (positional I/O, file identity, atomic writes, TGA files,
    # reading in halves...) built for Windows, to run under Wine with the DLL beside them.
    cargo test --target "$target" --no-default-features --lib --no-run
    cp "$out/bcryptprimitives.dll" "target/$target/debug/deps/"
    wine_prefix
    wineserver -p 300 2>/dev/null || true  # (already running: fine)
    trap 'wineserver -k 2>/dev/null || true' EXIT
    wine "$out/raytracer.exe" -help </dev/null >/dev/null 2>&1
    CARGO_TARGET_X86_64_PC_WINDOWS_GNU_RUNNER=wine cargo test --target "$target" --no-default-features --lib
    ;;
  viewer)
    install
    cargo build --release --target "$target"
    scaffolding
    ls -l "$out/raytracer.exe"
    ;;
  *)
    echo "usage: cargo xtask windows build|test|unit|viewer" >&2
    exit 2
    ;;
esac
