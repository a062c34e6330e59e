#!/usr/bin/env bash
# Regenerates the reports and pictures of docs/, then the README's tables copied from them.
#
# The generated reports and pictures of docs/ (docs/README.md lists each with what it shows),
# then the README's tables copied from them.
#   cargo xtask report              every report of the list below (about an hour on two cores)
#   cargo xtask report NAME…        only these, e.g. `cargo xtask report accuracy tradeoff`
#   cargo xtask report NAME ARG…    a word that is not a report's name is an argument of the report
#                                   before it: `cargo xtask report scaling 8 docs/scaling-<N>.md`
#   cargo xtask report sync         only the tables copied from the reports (marked
#                                   `<!-- from docs/NAME.md -->` in README.md and docs/)
# Reports: accuracy performance tradeoff mistakes diagnosis diagnosis-speed compare-diff memory
#   scaling thread-wake profile command-vs-cpp window-frame-times window-frame-times-wgpu
#   setup-times web windows windows-viewer screenshot readme-screenshots window-sizes fuzz
#   trace-example grading.
# Run by name only (not in the whole list): break-diagnosis [BREAK…] (each fit and rule of the
#   diagnosis broken in turn; DRY=1 only checks that each break applies); build-units (the test
#   profile's build from nothing, about 13 minutes on two cores: where its time goes).
# Those taking arguments: scaling [N [OUTPUT]] (on a machine without Rust, with release binaries
#   built elsewhere: `SCALING_BIN=DIR bash xtask/reports/scaling.sh N OUTPUT`), thread-wake
#   [N [OUTPUT]], profile [OUTPUT], windows [RUNS], window-frame-times [OUTPUT].
# The bodies of the longer reports are in xtask/reports/, each with its own header. A failure
# stops the run.
set -euo pipefail
cd "$(dirname "$0")/../.."

all=(accuracy performance tradeoff mistakes diagnosis diagnosis-speed compare-diff memory scaling
     thread-wake profile command-vs-cpp window-frame-times window-frame-times-wgpu setup-times web
     windows windows-viewer screenshot readme-screenshots window-sizes fuzz trace-example grading)
by_name_only=(break-diagnosis build-units sync)
source xtask/lib/pictures.sh

report() {
  local name=$1
  shift
  case "$name" in
    accuracy | performance | tradeoff) cargo run --release --example "$name" -- "$@" ;;
    mistakes)
      # The gallery's pictures are renders: they show no name.
      cargo run --release --example mistakes -- "$@" &&
        for picture in docs/mistakes/*.png; do
          record_picture "$picture" "cargo xtask report mistakes"
        done ;;
    diagnosis) cargo build --release && cargo run --release --example diagnosis_report -- "$@" ;;
    diagnosis-speed) cargo build --release && cargo run --release --example diagnosis_speed -- "$@" ;;
    compare-diff) bash xtask/reports/compare-example.sh "$@" ;;
    memory | scaling | thread-wake | profile | command-vs-cpp | window-frame-times | setup-times \
      | break-diagnosis | build-units)
      bash "xtask/reports/$name.sh" "$@" ;;
    window-frame-times-wgpu)
      RAYTRACER_RENDERER=wgpu bash xtask/reports/window-frame-times.sh docs/window-frame-times-wgpu.md ;;
    web) bash xtask/chores/web.sh report ;;
    windows) bash xtask/reports/windows.sh "${1:-11}" ;;
    windows-viewer) bash xtask/chores/screenshots.sh windows "$@" ;;
    screenshot) bash xtask/chores/screenshots.sh viewer "$@" ;;
    readme-screenshots) bash xtask/chores/screenshots.sh readme ;;
    window-sizes) bash xtask/chores/screenshots.sh sizes "$@" ;;
    grading)
      # The generated class graded and checked (docs/grading-speed.md), then its report's table
      # in headless Chromium (docs/grading.png).
      cargo build --release && cargo run --release --example grade_class 100 docs/grading-speed.md target/grading-report &&
        chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1300,900 \
          --screenshot=docs/grading.png "file://$PWD/target/grading-report/index.html" &&
        {
          # The names the page shows, read from the page itself: the course's lines and the
          # program's version.
          page=target/grading-report/index.html
          assignment=$(grep -o 'Assignment <code>[^<]*</code>' "$page" | head -n 1 | sed 's/.*<code>//; s/<.*//')
          version=$(grep -o 'Made by raytracer [0-9][0-9.]*[0-9]' "$page" | head -n 1 | awk '{ print $4 }')
          record_picture docs/grading.png "cargo xtask report grading" "file:$assignment" "version:$version"
        } ;;
    fuzz) bash xtask/chores/fuzz.sh 240 docs/fuzz && bash xtask/chores/fuzz.sh self-test ;;
    trace-example)
      cargo build --bin raytracer && scratch=$(mktemp -d) && {
        echo "\$ raytracer -input scenes/scene1_02.txt -depth 8 12 depth.tga -trace 60 140"
        target/debug/raytracer -input scenes/scene1_02.txt -depth 8 12 "$scratch/depth.tga" -trace 60 140
      } >docs/trace-example.txt && rm -rf "$scratch" ;;
    sync) ;;
  esac
}

is_report() {
  local known
  for known in "${all[@]}" "${by_name_only[@]}"; do
    [ "$known" = "$1" ] && return 0
  done
  return 1
}

# The words, split into runs: a report's name and the arguments after it.
runs=()
if [ $# -eq 0 ]; then
  runs=("${all[@]}")
else
  is_report "$1" || {
    echo "cargo xtask report: unknown report '$1' (cargo xtask report --help lists them)" >&2
    exit 2
  }
  for word in "$@"; do
    if is_report "$word"; then
      runs+=("$word")
    else
      runs[-1]+=$'\n'"$word"
    fi
  done
fi

for run in "${runs[@]}"; do
  mapfile -t words <<<"$run"
  echo "== ${words[*]}"
  started=$(date +%s)
  report "${words[@]}"
  echo "== ${words[0]}: $(( $(date +%s) - started )) s"
done
python3 xtask/reports/sync-tables.py
