#!/usr/bin/env bash
# tools/slurm/compare.sbatch runs a sweep (issue 12), with a stand-in for Slurm's srun that starts
# the ranks with mpirun as srun would: SLURM_NTASKS ranks, each told SLURM_CPUS_PER_TASK cores.
#   slurm_script_test.sh SOURCE_DIR USVID MPIEXEC WORK_DIR
set -euo pipefail
source_dir=$1 usvid=$2 mpiexec=$3 work=$4
rm -rf "$work" && mkdir -p "$work/bin"
cat > "$work/bin/srun" <<SRUN
#!/usr/bin/env bash
# srun OPTIONS... PROGRAM ARGS...: drop srun's own options, start the ranks with mpirun.
while [[ \$1 == --* ]]; do shift; done
exec "$mpiexec" -n "\$SLURM_NTASKS" --oversubscribe "\$@"
SRUN
chmod +x "$work/bin/srun"
cat > "$work/suite.json" <<'SUITE'
{"name": "slurm", "vessels": ["msd"], "train_maneuvers": ["random-steps"],
 "test_maneuvers": ["multisine"], "methods": ["sindy", "eb-lr"], "noise": [0.01],
 "seeds": [1, 2], "train_seconds": 60, "test_seconds": 30}
SUITE
export PATH="$work/bin:$PATH" SLURM_NTASKS=2 SLURM_CPUS_PER_TASK=1 USVID="$usvid"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$source_dir"
bash tools/slurm/compare.sbatch "$work/suite.json" "$work/out" 2> "$work/log"
grep -q "on 2 ranks" "$work/log" || { cat "$work/log"; echo "not 2 ranks"; exit 1; }
test -s "$work/out/results.json" || { cat "$work/log"; echo "no results.json"; exit 1; }
rows=$(grep -c '"test_maneuver"' "$work/out/results.json")
[ "$rows" -eq 4 ] || { echo "expected 4 rows, got $rows"; exit 1; }
# Submitted again (a job that timed out): everything is resumed, nothing recomputed.
bash tools/slurm/compare.sbatch "$work/suite.json" "$work/out" 2> "$work/log2"
grep -q "resuming: 4 of 4 cells" "$work/log2" || { cat "$work/log2"; echo "not resumed"; exit 1; }
echo "slurm script: 4 rows on 2 ranks, resubmission resumed all 4 cells"
