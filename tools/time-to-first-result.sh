#!/usr/bin/env bash
# A newcomer's time to the first result (issue 36), step by step: a fresh clone of this
# repository's HEAD, the README's set-up and build command with an empty compiler cache, then the
# default benchmark. Prints each step's wall and CPU time and, at the end, the slowest objects of
# ninja's log; the README's numbers are this script's output.
#   tools/time-to-first-result.sh [WORK_DIR]     (default: a new folder under /tmp, removed after)
# The clone is of the committed HEAD (uncommitted changes are not measured). The compiler cache
# is switched off (CCACHE_DISABLE=1), so every object is compiled, as on a new machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-}
if [ -z "$work" ]; then
  work=$(mktemp -d /tmp/usvid-first-result.XXXXXX)
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
export CCACHE_DISABLE=1

# step NAME COMMAND...: runs COMMAND, its output in $work/NAME.log, and prints its times.
step() {
  local name=$1
  shift
  local start end
  start=$(date +%s.%N)
  if ! /usr/bin/time -f "%U %S" -o "$work/$name.cpu" "$@" >"$work/$name.log" 2>&1; then
    tail -30 "$work/$name.log" >&2
    echo "time-to-first-result: step '$name' failed (log $work/$name.log)" >&2
    exit 1
  fi
  end=$(date +%s.%N)
  read -r user sys <"$work/$name.cpu"
  awk -v n="$name" -v w="$(echo "$start $end" | awk '{print $2 - $1}')" -v c="$user $sys" \
    'BEGIN { split(c, t, " "); printf "| %s | %.0f s | %.0f s |\n", n, w, t[1] + t[2] }'
}

echo "| step | wall | CPU |"
echo "| --- | ---: | ---: |"
step clone git clone --quiet --no-hardlinks "$root" "$work/usvid"
cd "$work/usvid"
step install-deps ./tools/install-deps.sh
step build cmake --workflow --preset default
step compare-quick ./build/usvid compare --quick --out "$work/quick"
step compare ./build/usvid compare --out "$work/results"

echo
echo "Slowest objects of the build (ninja's log, seconds):"
awk 'NR > 1 { printf "%6.1f %s\n", ($2 - $1) / 1000, $4 }' build/.ninja_log | sort -rn | sed -n 1,8p
echo
echo "The verdict: $work/results/summary.md"
