#!/usr/bin/env bash
# Coverage-guided fuzzing of the scene and command-line parsers, and the fuzzing's self-test.
#
# Coverage-guided fuzzing (cargo-fuzz: libFuzzer with AddressSanitizer, on the nightly toolchain)
# of the scene parser with what it renders (`scene`) and of the command-line parser (`command_line`).
#   cargo xtask fuzz [SECONDS [LOG_FOLDER]]
# runs each target (or those named in FUZZ_TARGETS, e.g. FUZZ_TARGETS=scene) for SECONDS (default 60, as CI does) from a copy of its committed seed corpus
# (fuzz/corpus/<target>), so the committed seeds stay as they are; with LOG_FOLDER, each target's
# whole libFuzzer log is written to LOG_FOLDER/<target>.log. A crash, a leak, a timeout (10 s for
# one input) or an input that takes more than 2 GB stops the run with a non-zero status and leaves
# the input in fuzz/artifacts/<target>/: make it a regression test. With FUZZ_PLANT_CRASH=1 an
# input the scene target crashes on is added to the corpus copy, to show that a crash fails the run
# (the self-test below).
#   cargo xtask fuzz self-test
# the fuzzing's own test: with the planted crash, a 10-second run must exit non-zero. Prints the
# statuses; exits 1 when a crash would pass unnoticed. CI runs it after the fuzzing.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ "${1:-}" = self-test ]; then
  set +e
  FUZZ_PLANT_CRASH=1 FUZZ_TARGETS=scene bash "$0" 10
  status=$?
  set -e
  rm -f "$root/fuzz/artifacts/scene/crash-2d07e24e67dd396ef40f6c48eb1cdcab7c4284c2"
  if [ "$status" -eq 0 ]; then
    echo "fuzz self-test: FAILED: a planted crash exited 0" >&2
    exit 1
  fi
  echo "fuzz self-test: a planted crash made cargo xtask fuzz exit $status, as it must"
  exit 0
fi
seconds=${1:-60}
if ! [[ "$seconds" =~ ^[0-9]+$ ]]; then
  echo "usage: cargo xtask fuzz [SECONDS [LOG_FOLDER]] | self-test" >&2
  exit 2
fi
logs=${2:-}
if [ -n "$logs" ]; then
  mkdir -p "$logs"
  logs=$(cd "$logs" && pwd)
fi
cd "$root/fuzz"
if ! rustup toolchain list | grep -q '^nightly'; then
  rustup toolchain install nightly --profile minimal
fi
if ! command -v cargo-fuzz >/dev/null 2>&1; then
  cargo install cargo-fuzz --locked
fi
cargo +nightly fuzz build --release
# Thread exits the leak check may see before they finish (fuzz/lsan-suppressions.txt says why).
export LSAN_OPTIONS="suppressions=$root/fuzz/lsan-suppressions.txt:print_suppressions=0"
# One target's run, its lines prefixed with its name; exits with libFuzzer's status.
fuzz_one() {
  local target=$1 corpus log status
  corpus=$(mktemp -d)
  cp corpus/"$target"/* "$corpus"/
  log=/dev/null
  if [ -n "$logs" ]; then
    mkdir -p "$logs"
    log="$logs/$target.log"
  fi
  echo "fuzzing $target for $seconds s"
  if [ -n "${FUZZ_PLANT_CRASH:-}" ]; then
    # The script's own test: an input the target crashes on (only with this variable set).
    printf 'planted crash' > "$corpus/planted-crash"
    export RAYTRACER_FUZZ_PLANTED_CRASH=1
  fi
  # The fuzzer's status is read from PIPESTATUS straight after the pipeline (grep's "no line
  # matched" and `|| true` would hide it otherwise).
  set +e +o pipefail
  cargo +nightly fuzz run --release "$target" "$corpus" -- \
    -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    2>&1 | sed -e "s#$root/##g" -e "s#$root#.#g" -e "s#$corpus#<copy of fuzz/corpus/$target>#g" | tee "$log" | grep --line-buffered -E '^(Done|stat::|==|SUMMARY|INFO: Seed)|ERROR|panicked' \
    | sed -u "s/^/$target: /"
  status=${PIPESTATUS[0]}
  set -e -o pipefail
  rm -rf "$corpus"
  if [ "$status" -ne 0 ]; then
    echo "fuzzing $target failed (status $status); the input is in fuzz/artifacts/$target/" >&2
    exit "$status"
  fi
}

# The targets at once, each libFuzzer on one core (a campaign is one process on one thread):
# the step takes SECONDS, not SECONDS per target.
pids=()
for target in ${FUZZ_TARGETS:-scene command_line}; do
  fuzz_one "$target" &
  pids+=($!)
done
failed=0
for pid in "${pids[@]}"; do
  wait "$pid" || failed=$?
done
exit "$failed"
