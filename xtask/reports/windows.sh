#!/usr/bin/env bash
# docs/windows.md: the Windows build's size and the course's command under Wine against the
# Linux binary (for interest: Wine is not Windows). Builds both command lines (release, no
# viewer, mimalloc), then the Windows viewer for its size.
#   cargo xtask report windows [RUNS]      (RUNS interleaved runs each, default 11)
set -euo pipefail
cd "$(dirname "$0")/../.."
runs="${1:-11}"
report=docs/windows.md
cargo xtask windows build >/dev/null
cargo build --release --no-default-features --features mimalloc >&2
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
cp target/x86_64-pc-windows-gnu/release/raytracer.exe target/x86_64-pc-windows-gnu/release/bcryptprimitives.dll "$folder/"
cp target/release/raytracer "$folder/raytracer-linux"
cp scenes/scene1_02.txt "$folder/"
cli_exe=$(stat -c %s "$folder/raytracer.exe")
x86_64-w64-mingw32-strip -o "$folder/stripped.exe" "$folder/raytracer.exe"
cli_stripped=$(stat -c %s "$folder/stripped.exe")
export WINEPREFIX="$PWD/target/wine-prefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
wineserver -p 60 2>/dev/null || true
timings=$(cd "$folder" && python3 - "$runs" <<'PY'
import statistics, subprocess, sys, time
runs = int(sys.argv[1])
def command(program, side):
    return program + ["-input", "scene1_02.txt", "-size", side, side,
                      "-output", "o.tga", "-depth", "8", "12", "d.tga"]
programs = {"Linux": ["./raytracer-linux"], "Windows under Wine": ["wine", "raytracer.exe"]}
for side in ["200", "2000"]:
    times = {name: [] for name in programs}
    for _ in range(runs):
        for name, program in programs.items():
            start = time.perf_counter()
            subprocess.run(command(program, side), check=True)
            times[name].append((time.perf_counter() - start) * 1000)
    linux = statistics.median(times["Linux"])
    wine = statistics.median(times["Windows under Wine"])
    print(f"| scene1_02 at {side}×{side}, both TGA files | {linux:.1f} ms | {wine:.1f} ms | {wine / linux:.1f}× |")
PY
)
cargo xtask windows viewer >/dev/null
viewer_exe=$(stat -c %s target/x86_64-pc-windows-gnu/release/raytracer.exe)
x86_64-w64-mingw32-strip -o "$folder/viewer-stripped.exe" target/x86_64-pc-windows-gnu/release/raytracer.exe
viewer_stripped=$(stat -c %s "$folder/viewer-stripped.exe")
mb() { python3 -c "print(f'{$1 / 1e6:.1f} MB')"; }
{
  echo "# The Windows build"
  echo
  echo "Written by \`cargo xtask report windows $runs\` on $(nproc) cores, $(date -u +%Y-%m-%d)."
  echo "Built for \`x86_64-pc-windows-gnu\` with Debian's mingw-w64 ($(x86_64-w64-mingw32-gcc -dumpversion)),"
  echo "run under $(wine --version)."
  echo
  echo "## Size of raytracer.exe"
  echo
  echo "| build | as built (line tables for backtraces) | stripped |"
  echo "|---|---|---|"
  echo "| command line only (\`--no-default-features --features mimalloc\`) | $(mb "$cli_exe") | $(mb "$cli_stripped") |"
  echo "| the whole program, viewer included (default features) | $(mb "$viewer_exe") | $(mb "$viewer_stripped") |"
  echo
  echo "## The course's command: Linux against Wine"
  echo
  echo "Median wall time of the whole command over $runs interleaved runs, process start included."
  echo "Wine is not Windows: its start-up (a Windows process under a server) is most of the small"
  echo "run, so this says little about the program on Windows itself."
  echo
  echo "| command | Linux | Windows under Wine | ratio |"
  echo "|---|---|---|---|"
  echo "$timings"
} > "$report"
cat "$report"
