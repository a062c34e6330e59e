#!/usr/bin/env bash
# Two builds of the renderer side by side on one machine, at 1 core and at CORES (default: all
# the machine has), to compare in one run (machines differ run to run by more than the change):
# the warm viewer frame (`examples/viewer_frame`, median of 15) of the three scenes of
# scripts/scaling.sh, the dense million's frame after 16 ms of idling, where `perf` is the context
# switches per warm frame, and the cold command's render_ms on the dense million (median of 5 fresh
# processes):
#   bash scripts/scaling-before-after.sh BEFORE_DIR AFTER_DIR [CORES]
# BEFORE_DIR holds `viewer_frame` and `raytracer`; AFTER_DIR holds `raytracer` and
# `examples/viewer_frame` (the layout of SCALING_BIN); the scenes are those scripts/scaling.sh
# made under target/scaling/. docs/scaling-16-before-after.txt is its output on the 16-core
# machine of docs/scaling-16.md, BEFORE_DIR built from the commit before the scaling work.
set -euo pipefail
cd "$(dirname "$0")/.."
before=$1
after=$2
most=${3:-$(nproc)}
d=target/scaling
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source scripts/pinned.sh

for s in dense_1e5 dense_1e6 random_1e6; do
  for c in 1 "$most"; do
    b=$(pinned "$c" "$before/viewer_frame" $d/$s.txt 1024 1024 15)
    a=$(pinned "$c" "$after/examples/viewer_frame" $d/$s.txt 1024 1024 15)
    echo "warm $s cores=$c before=$b after=$a"
  done
done
# Frames as a window has them, each after 16 ms of idling (the threads asleep).
for c in 1 "$most"; do
  b=$(pinned "$c" "$before/viewer_frame" $d/dense_1e6.txt 1024 1024 15 16)
  a=$(pinned "$c" "$after/examples/viewer_frame" $d/dense_1e6.txt 1024 1024 15 16)
  echo "warm after 16 ms idle dense_1e6 cores=$c before=$b after=$a"
done
# Where perf is: the process's context switches (voluntary and involuntary: mostly threads that
# ran out of work and slept) per warm frame, from 16 frames less 1.
perf=$(command -v perf || true)
if [ -n "$perf" ] && "$perf" stat -e context-switches true 2> /dev/null; then
  switches() {
    pinned "$most" "$perf" stat -x, -e context-switches "$@" 2>&1 > /dev/null |
      awk -F, '/context-switches/ { print $1 }'
  }
  for which in before after; do
    frame=$before/viewer_frame
    [ "$which" = after ] && frame=$after/examples/viewer_frame
    one=$(switches "$frame" $d/dense_1e6.txt 1024 1024 1)
    many=$(switches "$frame" $d/dense_1e6.txt 1024 1024 16)
    if [[ $one =~ ^[0-9]+$ && $many =~ ^[0-9]+$ ]]; then
      echo "context switches per warm frame dense_1e6 cores=$most $which $(( (many - one) / 15 ))"
    else
      echo "context switches per warm frame dense_1e6 cores=$most $which: perf counted none"
    fi
  done
fi
for c in 1 "$most"; do
  for which in before after; do
    bin=$before/raytracer
    [ "$which" = after ] && bin=$after/raytracer
    for _ in 1 2 3 4 5; do
      pinned "$c" "$bin" -input $d/dense_1e6.txt -size 1024 1024 -output "$work/c.tga" \
        -depth 0 100 "$work/d.tga" -stats | awk '/^render_ms:/ { print $2 }'
      rm -f "$work/c.tga" "$work/d.tga"
    done | sort -g | sed -n 3p | sed "s/^/cold dense_1e6 cores=$c $which render_ms=/"
  done
done
