#!/usr/bin/env bash
# Frame times where users feel them: the release viewer in a real window under Xvfb (software
# OpenGL, no GPU), driven with xdotool — a drag across the colour image (40 pointer moves, 30 ms
# apart) and 20 arrow-key presses (150 ms apart) — on a course scene and on the dense scenes of
# 100,000 and 1,000,000 spheres (`generate --dense`), at the window size 453×522 and 1600×900.
# The viewer logs every frame (RAYTRACER_FRAME_LOG, src/app/frame_log.rs): the render time the
# status bar shows, the input-to-new-frame latency, and the UI thread's time per frame. Beside
# them, the benchmark of the same view (examples/viewer_frame.rs), back to back and paced
# like the drag (30 ms of idling before each frame). Writes
# docs/window-frame-times.md, or the file given as the first argument. Needs xvfb and xdotool
# (cargo xtask test installs them). It also reads the CPU time of the viewer's threads from /proc:
# how much painting takes, per UI frame and of the two cores, beside the renderer's share. The
# window is painted with OpenGL unless RAYTRACER_RENDERER=wgpu:
# `RAYTRACER_RENDERER=wgpu cargo xtask report window-frame-times docs/window-frame-times-wgpu.md`
# measures the other renderer. Mesa's software painter runs on as many threads as there are
# cores; `LP_NUM_THREADS=1 cargo xtask report window-frame-times OUT.md`
# measures it on one, to show how much it competes with the render worker.
set -euo pipefail
cd "$(dirname "$0")/../.."
output=${1:-docs/window-frame-times.md}
cargo build --release --quiet
cargo build --release --quiet --example generate --example viewer_frame
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
target/release/examples/generate --dense 100000 "$work/dense_1e5.txt" 7 2>/dev/null
target/release/examples/generate --dense 1000000 "$work/dense_1e6.txt" 7 2>/dev/null
display=":95"
Xvfb "$display" -screen 0 1600x900x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true; rm -rf "$work"' EXIT
export DISPLAY="$display"
for _ in $(seq 100); do xdotool getmouselocation >/dev/null 2>&1 && break; sleep 0.1; done

# CPU milliseconds so far of the viewer's threads, as "GROUP MS" lines: paint (Mesa's painter
# threads, llvmpipe-N, and the UI thread, which is the process's first), render (the render
# worker and rayon's threads) and other.
tick_ms=$((1000 / $(getconf CLK_TCK)))
cores=$(nproc)
thread_cpu() {
  for task in /proc/"$1"/task/*; do
    [ -r "$task/stat" ] || continue
    name=$(cat "$task/comm" 2>/dev/null || true)
    # A thread that ended meanwhile is skipped (its CPU time leaves the process's tasks).
    ticks=$(sed 's/.*) //' "$task/stat" 2>/dev/null | awk '{print $12 + $13}' || true)
    [ -n "$ticks" ] || continue
    case "$name" in
      llvmpipe-*) group=paint ;;
      rayon-*|render-worker) group=render ;;
      *) if [ "$(basename "$task")" = "$1" ]; then group=paint; else group=other; fi ;;
    esac
    echo "$group $((ticks * tick_ms))"
  done | awk '{ms[$1] += $2} END {print "paint", ms["paint"] + 0; print "render", ms["render"] + 0; print "other", ms["other"] + 0}'
}
cpu_of() { awk -v g="$1" '$1 == g {print $2}' "$2"; }

# Percentile P (0-100) of the numbers in file $2.
percentile() { sort -g "$2" | awk -v p="$1" '{a[NR]=$1} END {i=int((NR-1)*p/100)+1; print a[i]}'; }

# The paced benchmark idles this long before each frame, as the drag's pointer moves come.
gap_ms=30
rows=""
renderers=""

for scene in scenes/scene1_02.txt "$work/dense_1e5.txt" "$work/dense_1e6.txt"; do
  case "$scene" in
    *dense_1e5*) name="dense, 100,000 spheres" ;;
    *dense_1e6*) name="dense, 1,000,000 spheres" ;;
    *) name="scene1_02 (course)" ;;
  esac
  for size in "453 522" "1600 900"; do
    read -r width height <<<"$size"
    home=$(mktemp -d -p "$work")
    log="$work/frames.log"
    rm -f "$log"
    HOME="$home" XDG_DATA_HOME="$home" XDG_CONFIG_HOME="$home" RAYTRACER_FRAME_LOG="$log" \
      target/release/raytracer -input "$scene" >/dev/null 2>&1 &
    viewer=$!
    window=$(timeout 120 xdotool search --sync --pid "$viewer" | head -n 1)
    xdotool windowmove "$window" 0 0 windowsize "$window" "$width" "$height"
    # Until the first frame of the full window is in (big scenes take a while to load).
    for _ in $(seq 600); do
      [ -s "$log" ] && [ "$(grep -c '^frame' "$log")" -ge 2 ] && break
      sleep 0.1
    done
    sleep 2
    start=$(wc -l <"$log")
    thread_cpu "$viewer" >"$work/cpu_before"
    started_ns=$(date +%s%N)
    # The colour image: left of the middle in a wide window (controls on the left), in the
    # upper half of a narrow one (images stacked or side by side below the toolbar).
    if [ "$width" -ge 900 ]; then x=$((320 + (width - 320) / 4)); y=$((height / 2)); else x=$((width / 4)); y=$((height / 3)); fi
    xdotool mousemove --window "$window" "$x" "$y" mousedown 1
    for _ in $(seq 40); do xdotool mousemove_relative -- 4 1; sleep 0.03; done
    xdotool mouseup 1
    sleep 1
    xdotool mousemove --window "$window" 5 $((height - 5))
    for _ in $(seq 20); do xdotool key --window "$window" Right 2>/dev/null; sleep 0.15; done
    sleep 2
    thread_cpu "$viewer" >"$work/cpu_after"
    wall_ms=$((($(date +%s%N) - started_ns) / 1000000))
    kill "$viewer" 2>/dev/null || true
    wait "$viewer" 2>/dev/null || true
    painted_with=$(awk '$1 == "renderer" {print $2; exit}' "$log")
    renderers="$renderers $painted_with"
    tail -n +"$((start + 1))" "$log" > "$work/run.log"
    grep '^frame' "$work/run.log" | awk '{print $2}' > "$work/render.txt"
    grep '^frame' "$work/run.log" | awk '$3 != "NaN" {print $3}' > "$work/latency.txt"
    grep '^ui' "$work/run.log" | awk '{print $2}' > "$work/ui.txt"
    frames=$(wc -l <"$work/render.txt")
    ui_frames=$(wc -l <"$work/ui.txt")
    paint_ms=$(($(cpu_of paint "$work/cpu_after") - $(cpu_of paint "$work/cpu_before")))
    render_ms=$(($(cpu_of render "$work/cpu_after") - $(cpu_of render "$work/cpu_before")))
    other_ms=$(($(cpu_of other "$work/cpu_after") - $(cpu_of other "$work/cpu_before")))
    if [ "$ui_frames" -gt 0 ]; then
      paint_per_frame=$(printf '%.1f' "$(echo "$paint_ms / $ui_frames" | bc -l)")
    else
      paint_per_frame="–"
    fi
    paint_share=$(echo "100 * $paint_ms / ($cores * $wall_ms)" | bc -l)
    render_share=$(echo "100 * $render_ms / ($cores * $wall_ms)" | bc -l)
    other_share=$(echo "100 * $other_ms / ($cores * $wall_ms)" | bc -l)
    read -r frame_width frame_height <<<"$(grep '^frame' "$work/run.log" | tail -n 1 | awk '{print $4, $5}')"
    bench=$(target/release/examples/viewer_frame "$scene" "$frame_width" "$frame_height" 15)
    paced=$(target/release/examples/viewer_frame "$scene" "$frame_width" "$frame_height" 15 "$gap_ms")
    render=$(percentile 50 "$work/render.txt")
    ratio=$(echo "$render / $bench" | bc -l)
    paced_ratio=$(echo "$render / $paced" | bc -l)
    rows+=$(printf '| %s | %s×%s | %s×%s | %d | %.1f | %.1f | %.2f× | %.1f | %.2f× | %.1f | %.1f | %.1f | %.1f | %d | %s | %.0f %% | %.0f %% | %.0f %% |' \
      "$name" "$width" "$height" "$frame_width" "$frame_height" "$frames" "$render" "$bench" "$ratio" \
      "$paced" "$paced_ratio" \
      "$(percentile 50 "$work/latency.txt")" "$(percentile 95 "$work/latency.txt")" \
      "$(percentile 50 "$work/ui.txt")" "$(percentile 95 "$work/ui.txt")" \
      "$ui_frames" "$paint_per_frame" "$paint_share" "$render_share" "$other_share")$'\n'
    rm -rf "$home"
  done
done
{
  echo "# Frame times in the real window"
  echo
  echo "Generated by \`cargo xtask report window-frame-times\` (do not edit by hand): the release viewer under"
  echo "Xvfb (no GPU: Mesa paints the window on the CPU, on the cores the render worker needs), a"
  echo "drag across the colour image and 20 arrow-key presses, each scene and window size a run of"
  echo "its own. *frame*: the render time the status bar shows (render, both textures,"
  echo "histogram), median over the frames of the run; *benchmark*: the same work for the same view"
  echo "size measured alone (\`examples/viewer_frame.rs\`, median of 15, frames back to back);"
  echo "*paced*: the same benchmark with $gap_ms ms of idling before each frame, as the drag's pointer"
  echo "moves come (the render's threads fall asleep between frames and must be woken, and what"
  echo "else runs on the machine cools the caches); *latency*: from the UI frame"
  echo "that applied the input to the one that takes the new picture in; *UI*: the UI thread's time"
  echo "per frame (layout, tessellation, painting), as eframe measures it; *UI frames*: how many"
  echo "frames the UI drew in the run; *paint CPU per UI frame*: the CPU time of the UI thread and"
  echo "of Mesa's painter threads (\`llvmpipe-N\`, which eframe's own figure leaves out) over the"
  echo "run, per UI frame; *paint share*, *render share* and *other share*: the part of the $cores cores'"
  echo "time over the run that painting, the renderer (the render worker and rayon's threads) and the"
  echo "viewer's other threads took."
  echo
  echo "This run: the window painted with $(echo $renderers | tr ' ' '\n' | sort -u | tr '\n' ' ' | sed 's/ $//')"
  echo "(as the viewer's frame log says; ${RAYTRACER_RENDERER:+\`RAYTRACER_RENDERER=$RAYTRACER_RENDERER\`, }see src/app/start/window.rs)."
  if [ -n "${LP_NUM_THREADS:-}" ]; then
    echo
    echo "This run: \`LP_NUM_THREADS=$LP_NUM_THREADS\`, Mesa's software painter on $LP_NUM_THREADS thread(s) instead of one per"
    echo "core."
  fi
  echo
  echo "| scene | window px | image px | frames | frame ms (p50) | benchmark ms | frame / benchmark | paced benchmark ms | frame / paced | latency ms p50 | latency ms p95 | UI ms p50 | UI ms p95 | UI frames | paint CPU ms per UI frame | paint share | render share | other share |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  printf '%s' "$rows"
} > "$output"
cat "$output"
