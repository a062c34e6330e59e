#!/usr/bin/env bash
# Where the test suite's time goes, from the log of a `cargo test` run without --quiet (cargo's
# "Running …" line before each test binary, libtest's "test result: … finished in S" after it):
# the build's time, then each binary's tests and seconds, the longest first.
#   bash xtask/reports/test-times.sh LOG [TITLE [SOURCE]]   writes the markdown to stdout; SOURCE,
#                                                            a paragraph saying whose log it is
# `cargo xtask report setup-times` runs it on the log of its fresh clone's `cargo xtask test`.
set -euo pipefail
log=$1
title=${2:-"Where the test suite's time goes"}
source=${3:-}
awk -v title="$title" -v source="$source" '
  /Finished `test` profile/ && build == "" { sub(/.* in /, ""); build = $0 }
  /^ *Running / { name = $2; if (name == "unittests") name = $3 " (unit tests)"; next }
  /^test result:/ && name != "" {
    passed = $4; seconds = $NF; sub(/s$/, "", seconds)
    if (!(name in secs)) order[++n] = name
    secs[name] += seconds; tests[name] += passed; total += seconds; name = ""
  }
  END {
    print "# " title
    print ""
    if (source != "") { print source; print "" }
    print "The build of the test profile: " build "."
    print ""
    print "| test binary | tests passed | seconds | share of the tests'"'"' time |"
    print "|---|---|---|---|"
    # The longest first (a plain selection sort: n is a few dozen).
    for (i = 1; i <= n; i++) done[i] = 0
    for (k = 1; k <= n; k++) {
      best = 0
      for (i = 1; i <= n; i++) if (!done[i] && (best == 0 || secs[order[i]] > secs[order[best]])) best = i
      done[best] = 1; b = order[best]
      printf "| `%s` | %d | %.1f | %.1f%% |\n", b, tests[b], secs[b], (total > 0 ? 100 * secs[b] / total : 0)
    }
    printf "| all | | %.1f | |\n", total
  }' "$log"
