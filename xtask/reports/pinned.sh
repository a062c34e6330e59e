# Sourced by cargo xtask report scaling and cargo xtask report thread-wake: `pinned C COMMAND…` runs a
# command on the first C cores (taskset, or Python's affinity call where util-linux is missing,
# as on a bare measuring machine).
pinned() {
  local c=$1; shift
  if command -v taskset > /dev/null; then
    taskset -c "0-$((c - 1))" "$@"
  else
    python3 -c 'import os, sys; os.sched_setaffinity(0, range(int(sys.argv[1]))); os.execv(sys.argv[2], sys.argv[2:])' "$c" "$@"
  fi
}
