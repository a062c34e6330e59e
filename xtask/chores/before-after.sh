#!/usr/bin/env bash
# Benchmarks two revisions in turns on this machine: a change's cost as the ratio of one run.
#
# A criterion benchmark of two revisions measured in turns on the same machine, so that a
# change's cost is read as a ratio from one run (the machine's drift between two separate runs
# was as large as the changes measured).
#   cargo xtask before-after BASE [ROUNDS] [FILTER] [BENCH]
# BASE: the revision to compare with the working tree (committed or not); ROUNDS (default 3):
# how many times each is run, alternately; FILTER: criterion's benchmark filter (default: the
# disc rasteriser's course, generated and dense frames); BENCH: the bench target (default render).
# Prints one line per benchmark: the median of each side's point estimates and after / before.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ $# -lt 1 ]; then
  echo "usage: cargo xtask before-after BASE [ROUNDS] [FILTER] [BENCH]" >&2
  exit 2
fi
base=$1
rounds=${2:-3}
filter=${3:-'course_2000x2000/scene1_0[27]$|generated_1024x1024/binned/(1000|100000)$|dense_1024x1024'}
bench=${4:-render}
work=$(mktemp -d)
trap 'git worktree remove --force "$work/base" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT

binary_of() { # the bench binary cargo builds in folder $1
  (cd "$1" && cargo bench --bench "$bench" --no-run --message-format=json 2>/dev/null) |
    python3 -c 'import json,sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m.get("executable") and m["target"]["kind"] == ["bench"]:
        print(m["executable"])' | tail -1
}

cp "$(binary_of .)" "$work/after"
git worktree add --detach "$work/base" "$base" >/dev/null 2>&1
# A target folder of its own: the same file name in the shared one would be the other side's.
CARGO_TARGET_DIR="$PWD/target/bench-base" binary_of "$work/base" >"$work/base_binary"
cp "$(cat "$work/base_binary")" "$work/before"

for round in $(seq "$rounds"); do
  for side in before after; do
    "$work/$side" --bench "$filter" --warm-up-time 1 --measurement-time 3 --noplot 2>/dev/null |
      awk -v side="$side" 'NF == 1 && $1 ~ /\// {name = $1}
        /time:/ { if ($1 != "time:") name = $1
          for (i = 1; i <= NF; i++) if ($i == "time:") print side, name, $(i + 3), $(i + 4) }' >>"$work/results"
  done
done

python3 - "$work/results" "$base" "$rounds" <<'PY'
import statistics, subprocess, sys
path, base, rounds = sys.argv[1:]
scale = {"ns": 1e-6, "µs": 1e-3, "us": 1e-3, "ms": 1.0, "s": 1e3}
runs = {}
for line in open(path):
    side, name, value, unit = line.split()
    runs.setdefault(name, {}).setdefault(side, []).append(float(value) * scale[unit])
head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
print(f"before: {base}; after: the working tree on {head}; {rounds} rounds each, in turns (ms, median of the rounds' estimates)")
print()
print("| benchmark | before ms | after ms | after / before |")
print("|---|---|---|---|")
for name, sides in runs.items():
    if "before" in sides and "after" in sides:
        b, a = statistics.median(sides["before"]), statistics.median(sides["after"])
        print(f"| {name} | {b:.3f} | {a:.3f} | {a / b:.3f} |")
PY
