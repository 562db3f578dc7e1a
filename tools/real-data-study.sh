#!/usr/bin/env bash
# Reproduces docs/real-data.md from the measured data in ../shared/data:
#   tools/real-data-study.sh [OUT]            (default OUT: results/real-data; usvid built first)
# 1. imports the KVLCC2 MARIN tests and the USV log (the log's rate of turn from its heading);
# 2. compares every method on them and on the Esso Osaka runs (docs/studies/*.json):
#    OUT/{kvlcc2,usv,esso}-compare/report.html;
# 3. diagnoses the nominal MMG model on each KVLCC2 test: OUT/diagnose_*/report.html;
# 4. the 20/20 zig-zag's first overshoots, measured, nominal and diagnosed: OUT/overshoots.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
usvid=${USVID:-$root/build/usvid}
data=${USVID_SHARED_DATA_DIR:-$root/../shared/data}
out=${1:-$root/results/real-data}
[ -x "$usvid" ] || { echo "real-data-study: build usvid first ($usvid)" >&2; exit 2; }
[ -d "$data/kvlcc2-marin" ] || { echo "real-data-study: no measured data at $data" >&2; exit 2; }
mkdir -p "$out"

for f in zz_20 zz_-20 tc_35; do
  "$usvid" import --format marin-dat --data "$data/kvlcc2-marin/MARIN_FREE_KVLCC2_${f}_m.dat" \
    --out "$out/kvlcc2_$f.csv"
done
"$usvid" import --format csv --data "$data/usv-fuzhou/zigzag_30_inter_xy.csv" \
  --map t=time,psi=psi,delta=delta,U=speed --rate-from psi --out "$out/usv.csv"

"$usvid" compare --suite "$root/docs/studies/kvlcc2-marin.json" --out "$out/kvlcc2-compare"
"$usvid" compare --suite "$root/docs/studies/usv-fuzhou.json" --out "$out/usv-compare"
"$usvid" compare --suite "$root/docs/studies/esso-osaka.json" --out "$out/esso-compare"
"$usvid" identify --method nomoto --states r --inputs delta --data "$out/usv.csv" \
  --out "$out/usv-nomoto.json"

for f in zz_20 zz_-20 tc_35; do
  "$usvid" diagnose --data "$out/kvlcc2_$f.csv" --vessel kvlcc2 --out "$out/diagnose_$f"
done

# First overshoot of a zig-zag record (usvid info --zigzag 20).
first_overshoot() {
  "$usvid" info --data "$1" --zigzag 20 | sed -n 's/.*reversal 1 at .*overshoot *\([-0-9.]*\) deg.*/\1/p'
}
{
  echo "| first turn | measured | nominal MMG | diagnosed (zz_20) | diagnosed (zz_-20) |"
  echo "| --- | --- | --- | --- | --- |"
  for turn in port starboard; do
    if [ "$turn" = port ]; then measured=zz_20; spec=zigzag:-20/20; else measured=zz_-20; spec=zigzag:20/20; fi
    row="| $turn | $(first_overshoot "$out/kvlcc2_$measured.csv")"
    "$usvid" simulate --vessel kvlcc2 --maneuver "$spec" --duration 300 --out "$out/sim.csv" 2>/dev/null
    row="$row | $(first_overshoot "$out/sim.csv")"
    for d in zz_20 zz_-20; do
      "$usvid" simulate --vessel kvlcc2 --maneuver "$spec" --duration 300 \
        --params "$out/diagnose_$d/model.json" --out "$out/sim.csv" 2>/dev/null
      row="$row | $(first_overshoot "$out/sim.csv")"
    done
    echo "$row |"
  done
} > "$out/overshoots.md"
rm -f "$out/sim.csv" "$out/sim.truth.json"
cat "$out/overshoots.md"
echo "real-data-study: wrote $out" >&2
