#!/usr/bin/env bash
# The tables of docs/vessels/odin-hs.md (issue 19): each method trained on 600 s of odin-hs random
# steps at 0.5 % noise, then free-run on a held-out random-step run and a held-out zig-zag, on
# the commands and on the jets' forces (`--forces waterjet`). Prints one markdown row per
# method, representation, seed and test: fit % of u / v / r, their mean, and the mean over u, v, r
# in each speed regime that holds more than 10 % of the rows.
# Usage: tools/odin-hs-study.sh [BUILD_DIR] [SEEDS] [METHODS]
#   defaults: build, "1 2 3", "fossen-ceres gp sindy eb-lr"
set -euo pipefail
cd "$(dirname "$0")/.."
usvid="$(realpath "${1:-build}")/usvid"
seeds="${2:-1 2 3}"
methods="${3:-fossen-ceres gp sindy eb-lr}"
[ -x "$usvid" ] || { echo "build first: cmake --workflow --preset default" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "| method | inputs | seed | test | u / v / r | mean | per regime (mean of u, v, r) | fit s |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for seed in $seeds; do
  "$usvid" simulate --vessel odin-hs --maneuver random-steps --duration 600 --noise 0.005 \
    --seed "$seed" --out "$work/train.csv" 2>/dev/null
  "$usvid" simulate --vessel odin-hs --maneuver random-steps --duration 600 --noise 0.005 \
    --seed $((seed + 1000)) --out "$work/random-steps.csv" 2>/dev/null
  "$usvid" simulate --vessel odin-hs --maneuver zigzag:20/20 --duration 300 --noise 0.005 \
    --seed $((seed + 2000)) --out "$work/zigzag.csv" 2>/dev/null
  for method in $methods; do
    for forces in none waterjet; do
      [ "$method" = fossen-ceres ] || [ "$method" = sindy ] || [ "$method" = eb-lr ] ||
        [ "$method" = gp ] || continue
      extra=()
      [ "$forces" = waterjet ] && extra+=(--forces waterjet)
      [ "$method" = gp ] && extra+=(--operators +,-,*,abs --threads 2)
      [ "$method" = fossen-ceres ] && extra+=(--rate 10)
      model="$work/$method-$forces.json"
      start=$(date +%s.%N)
      if ! "$usvid" identify --method "$method" --vessel odin-hs --data "$work/train.csv" \
        "${extra[@]}" --out "$model" 2>"$work/log"; then
        echo "| $method | $forces | $seed | - | failed: $(tail -1 "$work/log") | | | |"
        continue
      fi
      seconds=$(echo "$(date +%s.%N) - $start" | bc)
      for test in random-steps zigzag; do
        "$usvid" evaluate --model "$model" --data "$work/$test.csv" --out "$work/ev" 2>/dev/null
        python3 - "$method" "$forces" "$seed" "$test" "$work/ev/metrics.json" "$seconds" <<'EOF'
import json, sys
method, forces, seed, test, metrics_file, seconds = sys.argv[1:7]
m = json.load(open(metrics_file))
states = [s for s in ("u", "v", "r", "U") if s in m["channels"] and s != "U"] or ["U", "r"]
fits = [m[s]["fit_percent"] for s in states]
regimes = []
for name, scores in m.get("regimes", {}).items():
    share = scores["samples"] / m["samples"] if "samples" in m else 1.0
    if share > 0.10:
        regimes.append(f"{name} {sum(scores[s]['fit_percent'] for s in states) / len(states):.1f}")
div = " (diverged)" if m.get("diverged") else ""
print(f"| {method} | {'commands' if forces == 'none' else 'jet forces'} | {seed} | {test} | "
      f"{' / '.join(f'{f:.1f}' for f in fits)}{div} | {sum(fits) / len(fits):.1f} | "
      f"{', '.join(regimes)} | {float(seconds):.0f} |")
EOF
      done
    done
  done
done
