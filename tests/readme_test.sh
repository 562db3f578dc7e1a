#!/usr/bin/env bash
# The README's test command is the one CI runs: the last line of .ci/run must appear verbatim
# in the README right after its test-command marker.
set -euo pipefail
root=$1
ci_line=$(tail -n 1 "$root/.ci/run")
readme_line=$(sed -n '/<!-- test-command/,/^```$/p' "$root/README.md" | sed -n '3p')
if [ "$ci_line" != "$readme_line" ]; then
  echo "README test command:  $readme_line"
  echo ".ci/run test command: $ci_line"
  exit 1
fi
