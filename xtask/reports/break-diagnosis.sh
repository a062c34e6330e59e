#!/usr/bin/env bash
# Breaks each fit and each rule of the diagnosis's model, one at a time, in a scratch clone of
# this repository's HEAD, and runs the diagnosis's tests against each: every break must make a
# test fail. Writes the log to docs/break-diagnosis.txt (OUT overrides).
#
#   cargo xtask report break-diagnosis [NAME…]     # all breaks, or those named
#   DRY=1 cargo xtask report break-diagnosis       # only check that each break applies
#
# Release builds (the diagnosis's tests take minutes in a debug build); one build at a time. The
# scratch clone builds this crate incrementally in 16 codegen units (a break's rebuild is faster;
# the model's figures do not change), and its target folder starts as a copy of target/release
# where there is one (the dependencies are built once).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
out=${OUT:-$root/docs/break-diagnosis.txt}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
git clone -q "$root" "$scratch/repo"
export CARGO_TARGET_DIR=$root/target/break
if [ ! -d "$CARGO_TARGET_DIR/release" ] && [ -d "$root/target/release" ]; then
  mkdir -p "$CARGO_TARGET_DIR" && cp -a "$root/target/release" "$CARGO_TARGET_DIR/release"
fi
export CARGO_PROFILE_RELEASE_INCREMENTAL=true
cd "$scratch/repo"
sed -i 's/^codegen-units = 1$/codegen-units = 16/' Cargo.toml

# name ~ file ~ text ~ replacement (the text must occur exactly once; \n is a line break). A
# break must still compile: an entry of a fixed-size list is replaced by a copy of another.
breaks=$(cat <<'EOF'
no-file-order~src/compare/fit/hit_rule.rs~    for visible in [Visible::Nearest, Visible::FirstInFile, Visible::LastInFile] {~    for visible in [Visible::Nearest] {
no-near-root-only~src/compare/fit/hit_rule.rs~    (0.0, false, false),\n~    (0.0, true, false),\n
no-square-root-toggle~src/compare/fit/hit_rule.rs~        square_root: !rule.square_root,~        square_root: rule.square_root,
no-coordinate-quantity~src/compare/fit/depth.rs~    Quantity::AbsCoordinate(2),\n~    Quantity::AbsCoordinate(1),\n
no-wrapped-depth~src/compare/fit/depth.rs~[Outside::Clamp, Outside::Wrap, Outside::Black];~[Outside::Clamp, Outside::Clamp, Outside::Black];
no-rounded-bytes~src/compare/fit/colour.rs~    for rounded in [false, true] {~    for rounded in [false, false] {
no-other-background~src/compare/fit/colour.rs~        for background in [None, seen_background] {~        for background in [None, None] {
no-named-snap~src/compare/fit/mod.rs~        && results[first_named].0 <= results[0].0 + tolerance~        && false
no-polish~src/compare/fit/polish.rs~    let polished = polish_on(scorer, model, step, &[0, 1, 2, 3, 4, 5], true);~    let polished = *model;
few-lm-steps~src/compare/fit/mod.rs~const MORE_STEPS: usize = 40;~const MORE_STEPS: usize = 1;
no-untilted-refit~src/compare/fit/polish.rs~    if is_named_map(&view, &model) || levels > SMALL_TILT_LEVELS {~    if true {
no-rival-tilt-refit~src/compare/fit/mod.rs~            if fitted.model.t_ramp != glam::DVec3::ZERO && rival.t_ramp != fitted.model.t_ramp {~            if false {
no-rule-from-course-map~src/compare/fit/mod.rs~    let at_course = (scorer.score(&model) > 0\n~    let at_course = (false\n
no-only-block~src/compare/fit/starts.rs~    if width == height {\n        return None;~    if true {\n        return None;
keep-every-statement~src/compare/needed.rs~                *score <= left || ((*score - left) as f64) < *threshold~                false
EOF
)

wanted=("$@")
{
  echo "# Each fit and rule of the diagnosis broken in turn: the tests that must fail"
  echo "# made by cargo xtask report break-diagnosis at $(git rev-parse --short HEAD), $(date -u +%Y-%m-%d)"
  echo "# tests, in turn until one fails: cargo test --release --test diagnosis (its ignored tests included: generated::, compare::, course_mistakes::), then --test corpus (its ignored tests included)"
} >"$out"
held=0
while IFS='~' read -r name file text replacement; do
  [ -z "$name" ] && continue
  if [ ${#wanted[@]} -gt 0 ] && [[ ! " ${wanted[*]} " == *" $name "* ]]; then continue; fi
  BREAK_TEXT=$text BREAK_WITH=$replacement python3 - "$file" <<'PY'
import os, sys
path = sys.argv[1]
text = os.environ["BREAK_TEXT"].replace("\\n", "\n")
with_ = os.environ["BREAK_WITH"].replace("\\n", "\n")
source = open(path).read()
if source.count(text) != 1:
    sys.exit(f"{path}: the text to break occurs {source.count(text)} times: {text!r}")
open(path, "w").write(source.replace(text, with_))
PY
  if [ -n "${DRY:-}" ]; then
    verdict="applied (dry run)"
  elif cargo test --release --test diagnosis -- --include-ignored generated:: compare:: \
    course_mistakes:: >"$scratch/log" 2>&1 \
    && cargo test --release --test corpus -- --include-ignored >>"$scratch/log" 2>&1; then
    verdict="NOT CAUGHT"
    held=$((held + 1))
  else
    failed=$(grep -E "^test .* FAILED$|^error: could not compile" "$scratch/log" | sed 's/^test //; s/ \.\.\. FAILED$//' | paste -sd, -)
    verdict="caught: ${failed:-the build}"
  fi
  git checkout -q -- "$file"
  echo "$name ($file): $verdict" | tee -a "$out"
done <<<"$breaks"
echo "breaks not caught: $held" | tee -a "$out"
[ "$held" -eq 0 ]
