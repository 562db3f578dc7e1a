#!/usr/bin/env bash
# The whole test suite, stage by stage: the README's test command, and CI's (.ci/run). Each
# stage's wall time is printed as it ends, and all of them at the end (or at the stage that
# failed), so that a slow stage is seen before it eats CI's 90-minute limit.
#   install-deps  the build's and the tests' Debian packages (tools/install-deps.sh --test)
#   test          the normal build of everything and its tests (cmake --workflow --preset test)
#   sanitize      the input readers' tests and fuzzers under AddressSanitizer and
#                 UndefinedBehaviorSanitizer (clang 14; docs/reliability.md#sanitizers)
#   mpi           usvid compare over MPI ranks: it compiles harness/ranks_mpi.cc, and the compiler
#                 cache serves every other object from the test stage (the same flags)
#   fuzz          the CSV and equation libFuzzer targets for 60 s each (tools/fuzz.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
times=()
report() {
  local status=$?
  echo "test-all: stage times" >&2
  for line in "${times[@]}"; do echo "  $line" >&2; done
  [ "$status" -eq 0 ] || echo "test-all: FAILED in stage '$current'" >&2
}
trap report EXIT
start_all=$(date +%s)
stage() {
  current=$1
  shift
  echo "test-all: stage $current: $*" >&2
  local start=$(date +%s)
  "$@"
  local seconds=$(($(date +%s) - start))
  times+=("$(printf '%-13s %5d s' "$current" "$seconds")")
  echo "test-all: stage $current done in $seconds s" >&2
}
stage install-deps ./tools/install-deps.sh --test
stage test cmake --workflow --preset test
stage sanitize cmake --workflow --preset sanitize
stage mpi cmake --workflow --preset mpi
stage fuzz tools/fuzz.sh 60
times+=("$(printf '%-13s %5d s' all $(($(date +%s) - start_all)))")
