#!/usr/bin/env bash
# Regenerates the generated reports and pictures of docs/ (docs/README.md lists each with what it
# shows), then refreshes the README's tables copied from them.
#   bash scripts/reports.sh            every report (long: about an hour on two cores)
#   bash scripts/reports.sh NAME…      only these, e.g. `accuracy tradeoff screenshot`
# Names: accuracy performance tradeoff mistakes diagnosis diagnosis-speed compare-diff memory scaling thread-wake profile
# command-vs-cpp window-frame-times window-frame-times-wgpu setup-times web
# windows windows-viewer screenshot readme-screenshots window-sizes fuzz trace-example grading.
# Each runs the command docs/README.md names for it; a failure stops the script.
set -euo pipefail
cd "$(dirname "$0")/.."

all=(accuracy performance tradeoff mistakes diagnosis diagnosis-speed compare-diff memory scaling thread-wake profile command-vs-cpp
     window-frame-times window-frame-times-wgpu setup-times web
     windows windows-viewer screenshot readme-screenshots window-sizes fuzz trace-example grading)
wanted=("$@")
[ ${#wanted[@]} -eq 0 ] && wanted=("${all[@]}")

report() {
  case "$1" in
    accuracy) cargo run --release --example accuracy ;;
    performance) cargo run --release --example performance ;;
    tradeoff) cargo run --release --example tradeoff ;;
    mistakes) cargo run --release --example mistakes ;;
    diagnosis) cargo build --release && cargo run --release --example diagnosis_report ;;
    diagnosis-speed) cargo build --release && cargo run --release --example diagnosis_speed ;;
    compare-diff) bash scripts/compare-example.sh ;;
    memory) bash scripts/memory.sh ;;
    scaling) bash scripts/scaling.sh ;;
    thread-wake) bash scripts/thread-wake.sh ;;
    profile) bash scripts/profile.sh ;;
    command-vs-cpp) bash scripts/command-vs-cpp.sh ;;
    window-frame-times) bash scripts/window-frame-times.sh ;;
    window-frame-times-wgpu)
      RAYTRACER_RENDERER=wgpu bash scripts/window-frame-times.sh docs/window-frame-times-wgpu.md ;;
    setup-times) bash scripts/setup-times.sh ;;
    web) bash scripts/web.sh report ;;
    windows) bash scripts/windows-report.sh 11 ;;
    windows-viewer) bash scripts/windows-viewer-screenshot.sh ;;
    screenshot) bash scripts/screenshot.sh ;;
    readme-screenshots) bash scripts/readme-screenshots.sh ;;
    window-sizes) bash scripts/window-sizes.sh ;;
    grading)
      # The generated class graded and checked (docs/grading-speed.md), then its report's table
      # in headless Chromium (docs/grading.png).
      cargo build --release && cargo run --release --example grade_class 100 docs/grading-speed.md target/grading-report &&
        chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1300,900 \
          --screenshot=docs/grading.png "file://$PWD/target/grading-report/index.html" ;;
    fuzz) bash scripts/fuzz.sh 240 docs/fuzz && bash scripts/fuzz-self-test.sh ;;
    trace-example)
      cargo build --bin raytracer && scratch=$(mktemp -d) && {
        echo "\$ raytracer -input scenes/scene1_02.txt -depth 8 12 depth.tga -trace 60 140"
        target/debug/raytracer -input scenes/scene1_02.txt -depth 8 12 "$scratch/depth.tga" -trace 60 140
      } >docs/trace-example.txt && rm -rf "$scratch" ;;
    *) echo "reports.sh: unknown report '$1' (see the list at the top of this script)" >&2
       return 2 ;;
  esac
}

for name in "${wanted[@]}"; do
  echo "== $name"
  started=$(date +%s)
  report "$name"
  echo "== $name: $(( $(date +%s) - started )) s"
done
python3 scripts/sync-readme-tables.py
