#!/usr/bin/env bash
# The fuzz script's own test: with a planted input the scene target crashes on
# (FUZZ_PLANT_CRASH=1), scripts/fuzz.sh must exit non-zero. Prints the statuses; exits 1 when a
# crash would pass unnoticed. Run by .ci/run after the fuzzing step.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
FUZZ_PLANT_CRASH=1 FUZZ_TARGETS=scene bash "$root/scripts/fuzz.sh" 10
status=$?
rm -f "$root/fuzz/artifacts/scene/crash-2d07e24e67dd396ef40f6c48eb1cdcab7c4284c2"
if [ "$status" -eq 0 ]; then
  echo "fuzz self-test: FAILED: a planted crash exited 0" >&2
  exit 1
fi
echo "fuzz self-test: a planted crash made scripts/fuzz.sh exit $status, as it must"
