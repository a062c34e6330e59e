#!/usr/bin/env bash
# Where the test profile's build goes: cargo's own timings (`cargo test --no-run --timings`) of
# the README's test selection (the library, the program and the test binaries), built from
# nothing, read into docs/build-units.md (the wall time, the time of each group of units: this
# package's library and program, its test binaries, the dependencies, and the longest units) and
# docs/build-units.tsv (every unit: start and seconds).
#   cargo xtask report build-units            builds into target/build-units/ (emptied first;
#                                              about 13 minutes on two cores), then reads it
#   bash xtask/reports/build-units.sh HTML [COMMIT]   reads a timings page cargo wrote earlier
#                                  (target/cargo-timings/cargo-timing-*.html), built at COMMIT
set -euo pipefail
cd "$(dirname "$0")/../.."

html=${1:-}
if [ -z "$html" ]; then
  rm -rf target/build-units
  CARGO_INCREMENTAL=0 CARGO_TARGET_DIR=target/build-units \
    cargo test --lib --tests --no-run --timings
  html=$(ls -t target/build-units/cargo-timings/cargo-timing-*.html | head -1)
fi
commit=${2:-$(git rev-parse --short HEAD)}
python3 - "$html" "$commit" <<'PYTHON'
import json, re, sys
html, commit = sys.argv[1:]
text = open(html, encoding="utf-8").read()
units = json.loads(re.search(r"const UNIT_DATA = (\[.*?\]);\n", text, re.S).group(1))
when = re.search(r"cargo-timing-(\d{8})T", html)
wall = max(u["start"] + u["duration"] for u in units)
def group(u):
    if u["name"] != "raytracer":
        return "dependencies (and build scripts)"
    target = u["target"].strip()
    if target.startswith('"lib" (test)') or target.startswith('raytracer "lib" (test)'):
        return "raytracer: the library's unit tests"
    if "(test)" in target:
        return "raytracer: the test binaries (tests/*.rs) and the program's unit tests"
    return "raytracer: the library and the program"
with open("docs/build-units.tsv", "w", encoding="utf-8") as tsv:
    tsv.write("unit\ttarget\tstart_s\tseconds\n")
    for u in sorted(units, key=lambda u: u["start"]):
        tsv.write(f'{u["name"]} {u["version"]}\t{u["target"].strip() or "lib"}\t{u["start"]:.1f}\t{u["duration"]:.1f}\n')
sums, counts = {}, {}
for u in units:
    g = group(u)
    sums[g] = sums.get(g, 0) + u["duration"]
    counts[g] = counts.get(g, 0) + 1
total = sum(sums.values())
out = open("docs/build-units.md", "w", encoding="utf-8")
w = lambda line="": out.write(line + "\n")
w("# Where the test profile's build goes (2 cores)")
w()
w(f"cargo's timings of `cargo test --lib --tests --no-run --timings` from an empty target")
w(f"folder, at {commit}" + (f", {when.group(1)[:4]}-{when.group(1)[4:6]}-{when.group(1)[6:]}" if when else "") +
  ". Read by `bash xtask/reports/build-units.sh` (`cargo xtask report build-units` builds and")
w("reads). Every unit's start and seconds are in [build-units.tsv](build-units.tsv).")
w()
w(f"The build took {wall:.0f} s of wall time; its units' seconds add up to {total:.0f} s (two")
w("units compile at once on two cores).")
w()
w("| units | how many | seconds | share of the units' seconds |")
w("|---|---|---|---|")
for g in sorted(sums, key=lambda g: -sums[g]):
    w(f"| {g} | {counts[g]} | {sums[g]:.0f} | {100 * sums[g] / total:.1f}% |")
w()
w("The longest units:")
w()
w("| unit | target | started at (s) | seconds |")
w("|---|---|---|---|")
for u in sorted(units, key=lambda u: -u["duration"])[:15]:
    w(f'| {u["name"]} {u["version"]} | {u["target"].strip() or "lib"} | {u["start"]:.0f} | {u["duration"]:.1f} |')
PYTHON
echo "build-units.sh: docs/build-units.md and docs/build-units.tsv from $html"
