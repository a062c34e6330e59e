#!/usr/bin/env bash
# How the renderer scales with cores: the same table for 1, 2, 4, … cores up to N (N: the
# argument, or what the machine has), each measured with the process pinned to the first c cores
# (`taskset -c 0-(c-1)`), into docs/scaling.md (or OUTPUT) with a plot beside it (.svg):
#   cargo xtask report scaling [N [OUTPUT]]
# * warm viewer frame: `examples/viewer_frame` (render, textures, histogram) at 1024², the best
#   of 5 processes, each the median of 15 frames: dense 100,000 and 1,000,000 spheres and a
#   random million;
# * whole command, cold: the course's command (`-output c.tga -depth … d.tga`) at 1024², its
#   `-stats` render_ms, median of 5 fresh processes: dense 100k, dense 1M, scene1_02;
# * parse of the random million (`examples/parse_time`'s parse, median of 5);
# * where the warm frame's time goes, phase by phase (`examples/frame_phases`, median of 9), for
#   the three scenes, and the cold (first) frame of the dense million.
# The scenes are made once by `examples/generate` under target/scaling/. Speed-ups are ratios
# within one run (machines are noisy; compare nothing across runs). A few minutes on 2 cores.
# SCALING_BIN=DIR runs binaries built before (DIR/raytracer, DIR/examples/…) and builds nothing,
# for a machine without the toolchain.
set -euo pipefail
cd "$(dirname "$0")/../.."
# The command the report names: on a machine without Rust this file runs by itself.
how="cargo xtask report scaling"
[ -n "${SCALING_BIN:-}" ] && how="SCALING_BIN=DIR bash xtask/reports/scaling.sh"
max=${1:-$(nproc)}
output=${2:-docs/scaling.md}
plot="${output%.md}.svg"

bin=${SCALING_BIN:-target/release}
if [ -z "${SCALING_BIN:-}" ]; then
  cargo build --release --quiet
  cargo build --release --quiet --example viewer_frame --example parse_time --example generate \
    --example frame_phases
fi
data=target/scaling
mkdir -p "$data"
[ -f "$data/dense_1e5.txt" ] || "$bin/examples/generate" --dense 100000 "$data/dense_1e5.txt"
[ -f "$data/dense_1e6.txt" ] || "$bin/examples/generate" --dense 1000000 "$data/dense_1e6.txt"
[ -f "$data/random_1e6.txt" ] || "$bin/examples/generate" 1000000 "$data/random_1e6.txt"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cores=()
for c in 1 2 4 8 16 32 64; do [ "$c" -le "$max" ] && cores+=("$c"); done
[ "${cores[-1]}" -ne "$max" ] && cores+=("$max")
last=${cores[-1]}

source xtask/reports/pinned.sh

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# The warm viewer frame, best of 5 processes (each the median of 15 frames), on cores 0..c-1.
warm_ms() {
  local c=$1 scene=$2
  for _ in 1 2 3 4 5; do
    pinned "$c" "$bin/examples/viewer_frame" "$scene" 1024 1024 15
  done | sort -g | head -n 1
}

# The command's render_ms, median of 5 cold processes, on cores 0..c-1.
command_ms() {
  local c=$1 scene=$2 low=$3 high=$4
  for _ in 1 2 3 4 5; do
    pinned "$c" "$bin/raytracer" -input "$scene" -size 1024 1024 \
      -output "$work/c.tga" -depth "$low" "$high" "$work/d.tga" -stats |
      awk '/^render_ms:/ { print $2 }'
    rm -f "$work/c.tga" "$work/d.tga"
  done | median
}

rows=("warm viewer frame, dense 100k, ms" "warm viewer frame, dense 1M, ms"
      "warm viewer frame, random 1M, ms" "whole command render_ms (cold), dense 100k"
      "whole command render_ms (cold), dense 1M" "whole command render_ms (cold), scene1_02"
      "parse of the random 1M, ms")
declare -A value
for c in "${cores[@]}"; do
  echo "== $c core(s)" >&2
  pin=(pinned "$c")
  value[0,$c]=$(warm_ms "$c" "$data/dense_1e5.txt")
  value[1,$c]=$(warm_ms "$c" "$data/dense_1e6.txt")
  value[2,$c]=$(warm_ms "$c" "$data/random_1e6.txt")
  value[3,$c]=$(command_ms "$c" "$data/dense_1e5.txt" 0 100)
  value[4,$c]=$(command_ms "$c" "$data/dense_1e6.txt" 0 100)
  value[5,$c]=$(command_ms "$c" scenes/scene1_02.txt 8 12)
  value[6,$c]=$("${pin[@]}" "$bin/examples/parse_time" "$data/random_1e6.txt" 5 | awk '{ print $2 }')
  for scene in dense_1e5 dense_1e6 random_1e6; do
    "${pin[@]}" "$bin/examples/frame_phases" "$data/$scene.txt" 1024 1024 9 > "$work/phases_${scene}_$c"
  done
done

# A phase table: one row per phase (first seen at 1 core), one column per core count; FIELD 2 is
# the cold frame, 3 the warm median.
phase_table() {
  local scene=$1 field=$2
  printf '| phase |'; for c in "${cores[@]}"; do printf ' %s |' "$c"; done; printf ' %s vs 1 |\n' "$last"
  printf '|---|'; for _ in "${cores[@]}"; do printf -- '---|'; done; printf -- '---|\n'
  cut -f1 "$work/phases_${scene}_1" | while read -r phase; do
    printf '| %s |' "$phase"
    for c in "${cores[@]}"; do
      awk -F'\t' -v p="$phase" -v f="$field" '$1 == p { printf " %s |", $f; found = 1 }
        END { if (!found) printf " – |" }' "$work/phases_${scene}_$c"
    done
    # A count (thread sleeps) has no speed-up.
    awk -F'\t' -v p="$phase" -v f="$field" '$1 == p { print $f }' "$work/phases_${scene}_1" \
      "$work/phases_${scene}_$last" | paste -sd' ' |
      awk -v count="$([[ $phase == *"(count)"* ]] && echo 1)" \
        '{ if (!count && NF == 2 && $2 > 0) printf " %.2f× |\n", $1 / $2; else print " – |" }'
  done
}

cpu=$(awk -F': ' '/^model name/ { print $2; exit }' /proc/cpuinfo)
{
  echo "# Scaling with cores"
  echo
  echo "Generated by \`$how $max${2:+ $2}\` on $(nproc) cores ($cpu), $(date -u +%Y-%m-%d);"
  echo "each column pins the process to the first c cores with \`taskset\`. Milliseconds (lower is"
  echo "better); the last column is the 1-core time over the $last-core time, within this one run."
  echo "A warm viewer frame is the best of 5 processes, each the median of 15 frames; the whole"
  echo "command's render_ms the median of 5 fresh processes; the parse the median of 5."
  echo
  printf '| |'; for c in "${cores[@]}"; do printf ' %s |' "$c"; done; printf ' %s vs 1 |\n' "$last"
  printf '|---|'; for _ in "${cores[@]}"; do printf -- '---|'; done; printf -- '---|\n'
  for i in "${!rows[@]}"; do
    printf '| %s |' "${rows[$i]}"
    for c in "${cores[@]}"; do printf ' %s |' "${value[$i,$c]}"; done
    awk -v a="${value[$i,1]}" -v b="${value[$i,$last]}" 'BEGIN { printf " %.2f× |\n", a / b }'
  done
  echo
  echo "![speed-up against cores]($(basename "$plot"))"
  echo
  echo "## Where the frame's time goes"
  echo
  echo "The viewer's frame phase by phase (\`examples/frame_phases\`, \`raytracer::render::phases\`),"
  echo "milliseconds at 1024². A phase that stays flat as cores are added is a serial part. The"
  echo "histogram and the textures run at the same time, so the phases can add up to more than the"
  echo "frame; a dense frame's cull, sorting, binning and drawing are summed over its passes. The last row counts"
  echo "the times the process's threads slept during the frame (their voluntary context switches):"
  echo "each is a thread that ran out of work, which the next parallel step waits for to wake"
  echo "([thread-wake.md](thread-wake.md) measures what a wake costs)."
  for scene in dense_1e6 dense_1e5 random_1e6; do
    case $scene in
      dense_1e6) name="dense 1M" ;; dense_1e5) name="dense 100k" ;; random_1e6) name="random 1M" ;;
    esac
    echo
    echo "### $name, warm (median of 9)"
    echo
    phase_table "$scene" 3
  done
  echo
  echo "### dense 1M, cold (the first frame in a fresh process)"
  echo
  phase_table dense_1e6 2
} > "$output"

# The plot: each row's speed-up (1-core time over c-core time) against cores, with the ideal line.
{
  for i in "${!rows[@]}"; do
    printf '%s' "${rows[$i]}"
    for c in "${cores[@]}"; do printf '\t%s:%s' "$c" "${value[$i,$c]}"; done
    printf '\n'
  done
} | python3 -c '
import sys, html
rows = [line.rstrip("\n").split("\t") for line in sys.stdin if line.strip()]
series = [(r[0], [(int(c), float(v)) for c, v in (p.split(":") for p in r[1:])]) for r in rows]
cores = [c for c, _ in series[0][1]]
top = max(cores)
W, H, L, B = 820, 400, 60, 50
x = lambda c: L + (W - L - 360) * (c - 1) / max(top - 1, 1)
y = lambda s: H - B - (H - B - 20) * (s - 1) / max(top - 1, 1)
colours = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2"]
out = [f"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{W}\" height=\"{H}\" font-family=\"sans-serif\" font-size=\"11\">",
       f"<rect width=\"{W}\" height=\"{H}\" fill=\"white\"/>",
       f"<line x1=\"{x(1)}\" y1=\"{y(1)}\" x2=\"{x(top)}\" y2=\"{y(top)}\" stroke=\"#bbb\" stroke-dasharray=\"4 3\"/>",
       f"<text x=\"{x(top)-40}\" y=\"{y(top)-6}\" fill=\"#888\">ideal</text>",
       f"<line x1=\"{L}\" y1=\"{H-B}\" x2=\"{x(top)}\" y2=\"{H-B}\" stroke=\"black\"/>",
       f"<line x1=\"{L}\" y1=\"{H-B}\" x2=\"{L}\" y2=\"{y(top)}\" stroke=\"black\"/>",
       f"<text x=\"{(L+x(top))/2-20}\" y=\"{H-12}\">cores</text>",
       f"<text x=\"12\" y=\"{y(top)-8}\">speed-up over 1 core</text>"]
for c in cores:
    out.append(f"<text x=\"{x(c)-4}\" y=\"{H-B+16}\">{c}</text>")
    out.append(f"<text x=\"{L-24}\" y=\"{y(c)+4}\">{c}×</text>")
for k, (name, points) in enumerate(series):
    base = points[0][1]
    colour = colours[k % len(colours)]
    path = " ".join(f"{x(c):.1f},{y(base / v):.1f}" for c, v in points)
    out.append(f"<polyline points=\"{path}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"2\"/>")
    out.append(f"<text x=\"{W-340}\" y=\"{30 + 16*k}\" fill=\"{colour}\">{html.escape(name)}</text>")
out.append("</svg>")
print("\n".join(out))
' > "$plot"
echo "wrote $output and $plot" >&2
