#!/bin/bash
# The refinement comparison (issue 4, the paper's Section IV): coarse, fine and four dynamic
# runs of each problem, then the table and pictures (tools/compare_refinement.py).
#   tools/run_refinement.sh [bars|collapse ...]     (default: both)
#   ONLY='regex' tools/run_refinement.sh ...        (only the runs whose name matches)
#   TWO_LEVELS=1 tools/run_refinement.sh bars       (also maxlevel 2 against the lattice refined twice)
# Runs in examples/refinement/ on all cores; skips a run whose final dump is newer than the
# input and the binary (delete dump.*.final to force it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
[ -x "$build/lmp" ] || bash "$root/tools/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export LAMMPS_POTENTIALS=$root/potentials
np=${NP:-$(nproc)}
problems=("$@")
[ ${#problems[@]} -gt 0 ] || problems=(bars collapse)
cd "$root/examples/refinement"
for problem in "${problems[@]}"; do
  # the paper's four pairs, each also with the viscosity that follows the level (h0), and
  # (0.5, 0.5) at thresholds above the paper's 0.05
  runs=("coarse" "fine")
  for pair in "0.5 0.5" "0.55 0.5" "0.55 0.6" "0.55 0.7"; do runs+=("dynamic $pair 0"); done
  for pair in "0.5 0.5" "0.55 0.5" "0.55 0.6" "0.55 0.7"; do runs+=("dynamic $pair 1"); done
  for threshold in 0.1 0.2; do runs+=("dynamic 0.5 0.5 0 $threshold"); done
  # criteria beyond the paper's (bars only: their thresholds are the bars' rates and strains)
  if [ "$problem" = bars ]; then
    for threshold in 10 20; do runs+=("dynamic 0.5 0.5 0 $threshold shear_strain_rate"); done
    runs+=("dynamic 0.5 0.5 0 1.0 shear_strain")
    # two levels (maxlevel 2) against the lattice refined twice: the fine run alone takes about
    # 1.5 h on 2 cores, so only with TWO_LEVELS=1
    if [ "${TWO_LEVELS:-0}" = 1 ]; then
      runs+=("fine 0.5 0.5 0 0.05 strain 2" "dynamic 0.5 0.5 0 10 shear_strain_rate 2"
             "dynamic 0.5 0.5 0 0.05 strain 2")
    fi
  fi
  for run in "${runs[@]}"; do
    set -- $run
    mode=$1 eps=${2:-0.5} alpha=${3:-0.5} h0=${4:-0} threshold=${5:-0.05} criterion=${6:-strain}
    maxlevel=${7:-1}
    name=${problem}_${mode}
    [ "$mode" = dynamic ] && name=${problem}_dynamic_${eps}_${alpha}
    [ "$h0" = 1 ] && name=${name}_h0
    [ "$threshold" != 0.05 ] && name=${name}_t${threshold}
    [ "$criterion" != strain ] && name=${name}_${criterion}
    [ "$maxlevel" != 1 ] && name=${name}_L${maxlevel}
    # ONLY=regex: just the runs whose name matches
    if [ -n "${ONLY:-}" ] && ! [[ $name =~ $ONLY ]]; then continue; fi
    if [ -f "dump.$name.final" ] && [ "dump.$name.final" -nt in.refinement ] && [ "dump.$name.final" -nt "$build/lmp" ]; then
      echo "== $name: up to date"; continue
    fi
    echo "== $name"
    rm -f frame_${name}_*.png
    mpirun -np "$np" "$build/lmp" -in in.refinement -var problem "$problem" -var mode "$mode" \
      -var eps "$eps" -var alpha "$alpha" -var h0 "$h0" -var threshold "$threshold" \
      -var criterion "$criterion" -var maxlevel "$maxlevel" \
      -log "log.$name" -screen none \
      || echo "== $name stopped with an error (see log.$name)"
  done
done
/usr/bin/python3 "$root/tools/compare_refinement.py" --dir "$root/examples/refinement" "${problems[@]}"
