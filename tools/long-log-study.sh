#!/usr/bin/env bash
# Peak memory and time of usvid against the length of a log (docs/performance.md#long-logs):
# odin3dof random steps with 0.5 % noise at RATE Hz for each LENGTH (seconds), then info,
# identify (sindy, gp, fossen-ceres) and diagnose on it, each as its own process under
# /usr/bin/time. Prints one row per command and length: rows, MB of data as doubles, peak RSS
# [MB], its ratio to the data, seconds.
#   tools/long-log-study.sh BUILD_DIR OUT_DIR RATE LENGTH... [-- COMMANDS]
# e.g. tools/long-log-study.sh build /tmp/long 100 600 3600 7200 36000
# USVID_SENSOR_RATES=gps=1 samples those sensors slower (usvid simulate --rates), as a multi-rate
# log does; `info` then also prints what the channels hold (docs/data.md#multi-rate-channels).
set -euo pipefail
bin=$(cd "$1" && pwd)/usvid
out=$2
rate=$3
shift 3
lengths=()
while [[ $# -gt 0 && $1 != -- ]]; do lengths+=("$1"); shift; done
[[ ${1:-} == -- ]] && shift
commands=(info sindy gp fossen-ceres diagnose)
[[ $# -gt 0 ]] && commands=("$@")
mkdir -p "$out"
printf '%-8s %-13s %9s %8s %9s %6s %8s\n' length command rows data_MB peak_MB ratio seconds
for length in "${lengths[@]}"; do
  sensors=${USVID_SENSOR_RATES:-}
  data="$out/odin3dof_${length}s_${rate}hz${sensors:+_${sensors//[=,]/_}}.csv"
  [[ -f $data ]] || "$bin" simulate --vessel odin3dof --maneuver random-steps --duration "$length" \
    --rate "$rate" --noise 0.005 --seed 1 ${sensors:+--rates "$sensors"} --out "$data" 2>/dev/null
  rows=$(($(wc -l < "$data") - 1))
  cols=$(head -1 "$data" | tr ',' '\n' | wc -l)
  for command in "${commands[@]}"; do
    case $command in
      info) args=(info --data "$data") ;;
      diagnose) args=(diagnose --data "$data" --vessel odin3dof --out "$out/diagnose_$length") ;;
      *) args=(identify --method "$command" --data "$data" --vessel odin3dof
               --out "$out/${command}_$length.json") ;;
    esac
    /usr/bin/time -f '%M %e' -o "$out/time.txt" "$bin" "${args[@]}" > "$out/${command}_$length.out" \
      2> "$out/${command}_$length.err" || { echo "$command on $length s failed:"; tail -2 "$out/${command}_$length.err"; }
    read -r kb seconds < <(tail -1 "$out/time.txt")
    [[ $command == info ]] && grep '^held:' "$out/${command}_$length.out" >&2
    awk -v l="$length" -v c="$command" -v r="$rows" -v n="$cols" -v kb="$kb" -v s="$seconds" \
      'BEGIN { d = r * n * 8 / 1e6; printf "%-8s %-13s %9d %8.1f %9.1f %6.2f %8.1f\n", l, c, r, d, kb / 1e3, kb / 1e3 / d, s }'
  done
done
