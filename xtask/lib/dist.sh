# Sourced by the chores that build the program the downloads ship (the `dist` profile).
#   dist_build TARGET   builds raytracer for TARGET (into target/TARGET/dist/), in one cargo run
#                       with every target RAYTRACER_DIST_TARGETS names (space-separated)
#
# CI and `cargo xtask release build` name the host's target and Windows': one cargo run builds
# both programs, the build scripts and procedural macros once for both, and the last crate of
# each (one codegen unit, so one core) beside the other's. The two programs built apart took
# 7m 29s and 7m 20s in CI, together 10m 33s (docs/ci-steps.txt). Every build of them must then
# name both: cargo resolves the features of the dependencies over all the targets of a run
# (rustix asks libc for `extra_traits` only where it uses libc, on Windows), so a run for one
# target alone builds other units and compiles most crates again.
dist_build() {
  local targets target args=()
  targets=$(printf '%s\n' "$1" ${RAYTRACER_DIST_TARGETS:-} | LC_ALL=C sort -u)
  for target in $targets; do
    args+=(--target "$target")
  done
  cargo build --profile dist --bin raytracer "${args[@]}"
}
