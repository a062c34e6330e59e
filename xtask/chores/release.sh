#!/usr/bin/env bash
# The downloads: one archive per system and the page, made, then tested as a user meets them.
#
# The release artefacts: one download per system, and the page as a folder for any static host.
#   cargo xtask release build     all of them into target/artefacts/, with SHA256SUMS:
#       raytracer-VERSION-x86_64-linux.tar.gz    raytracer (viewer and command line)
#       raytracer-VERSION-x86_64-windows.zip     raytracer.exe (mingw-w64, icon and version info)
#       raytracer-VERSION-web.zip                the page (index.html, the wasm, the course scenes)
#     each with README.md, the licences (LICENSE-MIT, LICENSE-APACHE), the third-party notice
#     (THIRD-PARTY-LICENSES.html, committed) and the course scenes; a notice made from other
#     crates than Cargo.lock's fails the build;
#   cargo xtask release notice    THIRD-PARTY-LICENSES.html made again by cargo-about (installed
#     where missing): after a change of Cargo.lock, Cargo.toml's dependencies or features,
#     about.toml or about.hbs; a licence about.toml does not accept fails it;
#   cargo xtask release notice-check    whether THIRD-PARTY-LICENSES.html was made from what
#     the repository holds now (exit 1 and what to run when not);
#   cargo xtask release linux | windows | web | macos    one of them (macos: on a Mac, as
#     the release workflow builds it: raytracer-VERSION-universal-macos.tar.gz, one program for
#     Apple silicon and Intel);
#   cargo xtask release test [linux] [windows] [page]    the artefacts in target/artefacts/
#     as a user meets them (xtask/release/test.sh says what each part checks);
#   cargo xtask release sums      SHA256SUMS of what target/artefacts/ holds;
#   cargo xtask release sizes     docs/release-sizes.md: each archive's size, and the
#     programs' sizes unpacked, from what target/artefacts/ holds.
# The programs are built with the `dist` profile (Cargo.toml): the release profile the
# benchmarks measure, without debug information; the system's strip removes the symbols. Installs what it lacks (the Windows toolchain).
set -euo pipefail
cd "$(dirname "$0")/../.."

version=$(sed -n 's/^version = "\(.*\)"$/\1/p;T;q' Cargo.toml)
# The Linux program is built for the host named as a target (target/HOST/dist/), as the Windows
# one is: so both can be built by one cargo run (`build` below; xtask/lib/dist.sh).
host=$(rustc -vV | sed -n 's/^host: //p')
windows_target=x86_64-pc-windows-gnu
source xtask/lib/dist.sh
dist=target/artefacts
tools=target/tools
about_version=0.8.2

# What the notice is made from, as one line: the sha256 of Cargo.lock, of Cargo.toml's
# [features] and dependency tables (cargo-about follows the features the programs are built
# with), of about.toml and of about.hbs; and cargo-about's version.
notice_inputs() {
  {
    cat Cargo.lock
    awk '/^\[/ { keep = ($0 ~ /dependencies\]$/ || $0 == "[features]") } keep' Cargo.toml
    cat about.toml about.hbs
  } | sha256sum | awk -v about="$about_version" '{ print "cargo-about " about ", inputs sha256 " $1 }'
}

# The line THIRD-PARTY-LICENSES.html carries: what it was made from.
notice_stamp() {
  echo "<!-- made by cargo xtask release notice from $(notice_inputs) -->"
}

notice() {
  if [ "$("$tools/bin/cargo-about" --version 2>/dev/null | awk '{print $2}')" != "$about_version" ]; then
    echo "release.sh: installing cargo-about $about_version"
    # A tool run once needs no link-time optimisation: without it (and in 16 units) it builds
    # sooner.
    CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16 \
      cargo install cargo-about --version "$about_version" --locked --root "$tools" --quiet --force
  fi
  mkdir -p target
  # The default features: what the programs are built with (the viewer and mimalloc). Written
  # beside, then moved: a failed run leaves the committed notice as it was.
  "$tools/bin/cargo-about" generate --fail --locked -o target/THIRD-PARTY-LICENSES.html about.hbs
  { notice_stamp; cat target/THIRD-PARTY-LICENSES.html; } > target/THIRD-PARTY-LICENSES.html.new
  rm target/THIRD-PARTY-LICENSES.html
  mv target/THIRD-PARTY-LICENSES.html.new THIRD-PARTY-LICENSES.html
  echo "release.sh: wrote THIRD-PARTY-LICENSES.html ($(notice_inputs))"
}

# Whether the committed notice was made from what the repository holds now.
notice_check() {
  if [ "$(head -n 1 THIRD-PARTY-LICENSES.html 2>/dev/null)" != "$(notice_stamp)" ]; then
    echo "release.sh: THIRD-PARTY-LICENSES.html was not made from this Cargo.lock, Cargo.toml's" >&2
    echo "dependencies, about.toml and about.hbs: run \`cargo xtask release notice\` and commit it" >&2
    return 1
  fi
}

# The README and the licences, which every artefact carries, into folder $1.
papers() {
  cp README.md LICENSE-MIT LICENSE-APACHE THIRD-PARTY-LICENSES.html "$1/"
}

# What the programs' archives carry beside the program, into folder $1: the papers and the
# course scenes with their command lines.
extras() {
  local folder=$1
  papers "$folder"
  mkdir -p "$folder/scenes"
  cp scenes/*.txt scenes/assignment1.commands scenes/README.md "$folder/scenes/"
}

# A reproducible archive: files in name order, owner and times fixed.
tarball() {
  local name=$1
  tar --sort=name --owner=0 --group=0 --numeric-owner --mtime='2000-01-01 00:00Z' \
    -C "$dist" -czf "$dist/$name.tar.gz" "$name"
  rm -rf "${dist:?}/$name"
}

# A zip of folder $dist/$1's files, without the folder: Windows' "Extract All" and a web host's
# folder take the files as they are.
zipped() {
  local name=$1
  rm -f "$dist/$name.zip"
  (cd "$dist/$name" && find . -type f | LC_ALL=C sort | TZ=UTC zip -X -q -@ "../$name.zip")
}

linux() {
  notice_check
  dist_build "$host"
  local name="raytracer-$version-x86_64-linux"
  rm -rf "${dist:?}/$name"
  mkdir -p "$dist/$name"
  strip -o "$dist/$name/raytracer" "target/$host/dist/raytracer"
  extras "$dist/$name"
  tarball "$name"
}

macos() {
  notice_check
  local name="raytracer-$version-universal-macos" target
  rm -rf "${dist:?}/$name"
  mkdir -p "$dist/$name"
  for target in aarch64-apple-darwin x86_64-apple-darwin; do
    cargo build --profile dist --target "$target" --bin raytracer
  done
  # One program for Apple silicon and Intel.
  lipo -create -output "$dist/$name/raytracer" \
    target/aarch64-apple-darwin/dist/raytracer target/x86_64-apple-darwin/dist/raytracer
  strip -x "$dist/$name/raytracer"
  extras "$dist/$name"
  tarball "$name"
}

windows() {
  notice_check
  cargo xtask windows install
  local target=$windows_target
  dist_build "$target"
  local name="raytracer-$version-x86_64-windows"
  rm -rf "${dist:?}/$name"
  mkdir -p "$dist/$name"
  # The symbol table (8 MB of 36): mingw-w64's own strip removes it.
  x86_64-w64-mingw32-strip -o "$dist/$name/raytracer.exe" "target/$target/dist/raytracer.exe"
  extras "$dist/$name"
  zipped "$name"
  rm -rf "${dist:?}/$name"
}

web() {
  notice_check
  cargo xtask web build
  local name="raytracer-$version-web"
  rm -rf "${dist:?}/$name"
  mkdir -p "$dist/$name"
  cp -r target/web/. "$dist/$name/"
  papers "$dist/$name"
  zipped "$name"
  rm -rf "${dist:?}/$name"
}

sums() {
  (cd "$dist" && sha256sum -- raytracer-"$version"-* > SHA256SUMS)
  echo "release.sh: target/artefacts/ (version $version):"
  (cd "$dist" && for file in raytracer-"$version"-*; do
    stat -c '%s %n' "$file"
  done) | awk '{ printf "  %-40s %6.1f MB\n", $2, $1 / 1e6 }'

}

sizes() {
  local out=docs/release-sizes.md
  {
    echo "# Release archives: sizes"
    echo
    echo "Made by \`cargo xtask release build\` then \`cargo xtask release sizes\`, from commit"
    echo "$(git describe --always --dirty --abbrev=12) (version $version; the target is 15 MB for each download)."
    echo
    echo "| archive | compressed | the program in it, unpacked |"
    echo "|---|---|---|"
    local file program
    for file in "$dist"/raytracer-"$version"-*; do
      case "$file" in
        *.tar.gz) program=$(tar -tvzf "$file" | awk '$6 ~ /\/raytracer$/ { print $3 }') ;;
        *web.zip) program=$(unzip -l "$file" | awk '$4 ~ /raytracer_bg.wasm$/ { print $1 }') ;;
        *.zip) program=$(unzip -l "$file" | awk '$4 ~ /raytracer.exe$/ { print $1 }') ;;
      esac
      awk -v name="$(basename "$file")" -v size="$(stat -c %s "$file")" -v program="$program" \
        'BEGIN { printf "| %s | %.1f MB | %.1f MB |\n", name, size / 1e6, program / 1e6 }'
    done
    local linux="$dist/raytracer-$version-x86_64-linux.tar.gz"
    if [ -f "$linux" ]; then
      local glibc
      glibc=$(tar -xzOf "$linux" "raytracer-$version-x86_64-linux/raytracer" >"$dist/linux-program" &&
        objdump -T "$dist/linux-program" | grep -o 'GLIBC_[0-9.]*' | sort -uV | tail -n 1)
      rm -f "$dist/linux-program"
      echo
      echo "The Linux program needs ${glibc/GLIBC_/glibc } or newer (the newest version its symbols"
      echo "name, \`objdump -T\`): Debian 12, Ubuntu 22.04 and later."
    fi
  } >"$out"
  echo "release.sh: wrote $out"
}

case "${1:-}" in
  build)
    notice_check
    rm -rf "$dist"
    # Both programs in one cargo run (xtask/lib/dist.sh): the Windows toolchain first.
    cargo xtask windows install
    RAYTRACER_DIST_TARGETS="$host $windows_target ${RAYTRACER_DIST_TARGETS:-}"
    export RAYTRACER_DIST_TARGETS
    linux
    windows
    web
    sums
    ;;
  linux | windows | web | macos | notice | sums | sizes)
    "$1"
    ;;
  notice-check)
    notice_check
    ;;
  test)
    shift
    bash xtask/release/test.sh "$@"
    ;;
  *)
    echo "usage: cargo xtask release build | linux | windows | web | macos | notice | notice-check | sums | sizes | test [PART…]" >&2
    exit 2
    ;;
esac
