#!/usr/bin/env bash
# The tables of docs/replication.md: the reference report's experiments re-run with GP-SR at
# `--preset report` (its Table 3.1 exactly) and at usvid's defaults, each model scored in free
# run on clean held-out data (`usvid evaluate`: fit % per state, and whether it diverged).
# About 5 minutes on 2 cores. Usage: tools/replication.sh [BUILD_DIR] (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
usvid="$(realpath "${1:-build}")/usvid"
[ -x "$usvid" ] || { echo "build first: cmake --workflow --preset default" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

sim() {  # sim NAME VESSEL MANEUVER SECONDS NOISE SEED [simulate options...]
  local name=$1 vessel=$2 maneuver=$3 seconds=$4 noise=$5 seed=$6
  shift 6
  "$usvid" simulate --vessel "$vessel" --maneuver "$maneuver" --duration "$seconds" \
    --noise "$noise" --seed "$seed" "$@" --out "$work/$name.csv" 2>/dev/null
}

# row LABEL TRAIN TEST PRESET OPERATORS [identify options...]: one table row.
row() {
  local label=$1 train=$2 test=$3 preset=$4 ops=$5
  shift 5
  local vessel
  vessel=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["vessel"])' \
    "$work/$train.truth.json")
  local model="$work/$train-$preset-$RANDOM.json"
  "$usvid" identify --method gp --vessel "$vessel" --data "$work/$train.csv" --preset "$preset" \
    --operators "$ops" --threads 2 "$@" --out "$model" 2>/dev/null
  "$usvid" evaluate --model "$model" --data "$work/$test.csv" --out "$work/ev" 2>/dev/null
  python3 - "$label" "$preset" "$model" "$work/ev/metrics.json" <<'EOF'
import json, re, sys
label, preset, model_file, metrics_file = sys.argv[1:5]
model, metrics = json.load(open(model_file)), json.load(open(metrics_file))
short = lambda e: re.sub(r"-?\d+\.\d+(e-?\d+)?", lambda m: f"{float(m.group()):.3g}", e)
fits = " / ".join(f"{metrics['channels'][s]['fit_percent']:.1f}" for s in model["equations"])
eqs = "<br>".join(f"{s}' = {short(e)}" for s, e in model["equations"].items())
delay = model.get("preprocessing", {}).get("delay_s", 0.0)
extra = f" (delay {delay:.2f} s)" if delay else ""
diverged = " (diverged)" if metrics["diverged"] else ""
print(f"| {label} | {preset} | {fits}{diverged}{extra} | {eqs} |")
EOF
}

header() {
  echo
  echo "### $1"
  echo
  echo "| data | preset | held-out fit % ($2) | equations |"
  echo "| --- | --- | --- | --- |"
}

# 1. Mass-spring-damper (report section 3.2): noise from none to the signal's scale, and 20 %
#    of the data; operators + - * (the report's), held-out multisine.
sim msd-test msd multisine 300 0 101
header "MSD: noise, and 20 % of the data (report section 3.2)" "v"
for noise in 0 0.01 0.1 1; do
  sim "msd-$noise" msd random-steps 300 "$noise" 1
  for preset in report default; do
    row "random steps, noise $noise" "msd-$noise" msd-test "$preset" "+,-,*"
  done
done
sim msd-short msd random-steps 60 0.01 1
for preset in report default; do
  row "60 s of the 300 s (20 %), noise 0.01" msd-short msd-test "$preset" "+,-,*"
done

# 2. The 0.5 s input delay (report Figs 3.4-3.6, 3.14): on the MSD at 100 Hz and on the 3-DOF
#    forces; the report's preset without delay handling, the default with --delay auto.
sim msd-late msd random-steps 300 0.01 1 --rate 100 --effect input_delay=0.5
sim msd-late-test msd multisine 300 0 101 --rate 100 --effect input_delay=0.5
header "Input delay 0.5 s (report Figs 3.4, 3.6 and 3.14)" "MSD v; 3-DOF u / v / r"
row "MSD, 1 % noise" msd-late msd-late-test report "+,-,*"
row "MSD, 1 % noise, --delay auto" msd-late msd-late-test default "+,-,*" --delay auto
sim odin-late odin3dof random-steps 600 0.005 1 --effect input_delay=0.5
sim odin-late-test odin3dof multisine 300 0 101 --effect input_delay=0.5
row "3-DOF random steps, 0.5 % noise" odin-late odin-late-test report "+,-,*"
row "3-DOF, --delay auto" odin-late odin-late-test default "+,-,*,abs" --delay auto

# 3. The 3-DOF data sets trained and tested crosswise (report section 3.3, eq. 3.18-3.19):
#    set 1 input steps, set 2 multisine inputs.
sim set1 odin3dof random-steps 600 0.005 1
sim set2 odin3dof multisine 600 0.005 2
sim set1-test odin3dof random-steps 300 0 11
sim set2-test odin3dof multisine 300 0 12
header "3-DOF crosswise: set 1 input steps, set 2 multisine (report section 3.3)" "u / v / r"
for preset in report default; do
  ops=$([ "$preset" = report ] && echo "+,-,*" || echo "+,-,*,abs")
  row "train set 1, test set 2" set1 set2-test "$preset" "$ops"
  row "train set 2, test set 1" set2 set1-test "$preset" "$ops"
done

# 4. Zig-zag against step-series training (report Figs 3.10-3.13), tested on set 2.
sim zigzag odin3dof zigzag:20/20 600 0.005 1
sim steps odin3dof stepgrid 0 0.005 1
header "3-DOF zig-zag against step-series training, tested on multisine (report Figs 3.12, 3.13)" "u / v / r"
for preset in report default; do
  ops=$([ "$preset" = report ] && echo "+,-,*" || echo "+,-,*,abs")
  row "train zig-zag 20/20" zigzag set2-test "$preset" "$ops"
  row "train step grid" steps set2-test "$preset" "$ops"
done
