#!/usr/bin/env bash
# Builds the libFuzzer targets in the sanitize preset's tree (clang 14, ASan + UBSan; after
# `cmake --workflow --preset sanitize` they are built) and runs each for SECONDS (default 60) on a
# copy of its seed corpus (tests/fuzz_corpus/NAME); a crash, a sanitizer report or an escaped
# exception fails the run and leaves the input in OUT (default build-sanitize/fuzz-runs). The
# preset builds the csv and expression fuzzers; the suite fuzzer links the whole library:
#   USVID_FUZZERS="csv;expression;suite" tools/fuzz.sh 600
# An existing sanitize tree is used as it is configured.
#   [USVID_FUZZERS=...] tools/fuzz.sh [SECONDS] [OUT]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
out=${2:-$root/build-sanitize/fuzz-runs}
cd "$root"
if [ -n "${USVID_FUZZERS:-}" ]; then
  cmake --preset sanitize -DUSVID_FUZZERS="$USVID_FUZZERS" >/dev/null
elif [ ! -f build-sanitize/CMakeCache.txt ]; then
  cmake --preset sanitize >/dev/null
fi
cmake --build build-sanitize --target usvid_fuzzers >/dev/null
mkdir -p "$out"
for name in csv expression suite; do
  [ -x "$root/build-sanitize/fuzz/${name}_fuzzer" ] || continue
  corpus="$out/$name-corpus"
  rm -rf "$corpus" && mkdir -p "$corpus"
  cp "$root/tests/fuzz_corpus/$name"/* "$corpus/"
  echo "fuzz: $name for ${seconds} s" >&2
  "$root/build-sanitize/fuzz/${name}_fuzzer" -max_total_time="$seconds" -max_len=4096 \
    -artifact_prefix="$out/$name-" -print_final_stats=1 "$corpus" 2> "$out/$name.log" ||
    { tail -40 "$out/$name.log" >&2; echo "fuzz: $name FAILED (log $out/$name.log)" >&2; exit 1; }
  grep -E "stat::number_of_executed_units|Done [0-9]+ runs" "$out/$name.log" | tail -2 >&2
done
echo "fuzz: no crash in ${seconds} s per target" >&2
