#!/usr/bin/env bash
# The recovery tables of docs/gp.md: GP-SR on odin3dof random steps (900 s), 10 seeds, each
# identified right-hand side against the true one on a clean held-out multisine run; the
# defaults before this project changed them (--preset report: the reference report's Table 3.1)
# and after, at 0.5 % and 2 % noise, with + - * and with + - * abs. About 10 minutes on 2 cores.
# Usage: tools/gp-recovery-tables.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
tool="${1:-build}/tools/gp_recovery/usvid_gp_recovery"
[ -x "$tool" ] || { echo "build first: cmake --workflow --preset default" >&2; exit 2; }
for preset in report default; do
  for operators in "+,-,*,abs" "+,-,*"; do
    for noise in 0.005 0.02; do
      within=$([ "$noise" = 0.005 ] && echo 0.02 || echo 0.05)
      echo "### --preset $preset, --operators $operators, noise $noise (recovered: all three within $(awk "BEGIN{print 100*$within}") %)"
      echo
      "$tool" --seeds 10 --noise "$noise" --within "$within" --preset "$preset" \
        --operators "$operators" --threads 2 2>/dev/null
      echo
    done
  done
done
