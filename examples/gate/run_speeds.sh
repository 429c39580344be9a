#!/bin/bash
# The gate example at several lift speeds against the instantaneous release: runs in.gate for
# each speed and in.aluminium_bars, each in its own directory under OUT (not in the source
# tree), then tools/plot_gate.py on them (gate.png, gate.json here), and copies the output of
# the default speed (1 m/s: gate_force.dat, log.gate.run, the frames at 0.06 s and 0.11 s after
# the start of the lift and the final one) into this directory. One run at a time, NP ranks.
#
#   bash examples/gate/run_speeds.sh                       # 2 mm, 0.25 0.5 1 2 m/s (~6 min, 2 cores)
#   bash examples/gate/run_speeds.sh -var gate_slip noslip # extra lmp arguments go to every run
#   SPEEDS="0.5 1" NP=4 OUT=/tmp/gate bash examples/gate/run_speeds.sh
#   PLOT_ONLY=1 bash examples/gate/run_speeds.sh           # only the plot, from the runs in OUT
#
# environment: LMP (the LAMMPS binary, default build/lmp of SPH_SOIL), NP (2), MPIRUN (mpirun),
# SPEEDS ("0.25 0.5 1 2"), OUT (/tmp/sph_soil_gate), PLOT_ONLY (1: run nothing).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$root/tools/build_dir.sh"
lmp=${LMP:-$build/lmp}
np=${NP:-2}
mpirun=${MPIRUN:-mpirun}
speeds=${SPEEDS:-0.25 0.5 1 2}
out=${OUT:-/tmp/sph_soil_gate}
export LAMMPS_POTENTIALS=${LAMMPS_POTENTIALS:-$root/potentials}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

run() {    # run DIR INPUT LOGNAME [lmp arguments]
  local dir=$1 input=$2 log=$3
  shift 3
  mkdir -p "$dir"
  local start
  start=$(date +%s)
  (cd "$dir" && "$mpirun" -np "$np" "$lmp" -in "$input" -log "$log" -screen none "$@")
  echo "run_speeds: $dir done in $(( $(date +%s) - start )) s on $np ranks"
}

dirs=()
for speed in $speeds; do
  dir=$out/speed_$speed
  [ -n "${PLOT_ONLY:-}" ] || run "$dir" "$here/in.gate" log.gate.run -var speed "$speed" "$@"
  dirs+=("$speed m/s=$dir")
done
[ -n "${PLOT_ONLY:-}" ] || run "$out/instantaneous" "$root/examples/aluminium_bars/in.aluminium_bars" \
  log.aluminium_bars.run "$@"
dirs+=("instantaneous=$out/instantaneous")

/usr/bin/python3 "$root/tools/plot_gate.py" --json "$here/gate.json" --plot "$here/gate.png" "${dirs[@]}"

# the default speed's output next to the input
default=$out/speed_1
if [ -f "$default/gate_force.dat" ]; then
  cp "$default/gate_force.dat" "$default/log.gate.run" "$here/"
  rm -f "$here"/frame.*.png
  frames=$(ls "$default"/frame.*.png | sort)
  # the frames at 0.06 s and 0.11 s after the start of the lift and the last one (not t = 0)
  for f in $(echo "$frames" | tail -n +2 | head -2) $(echo "$frames" | tail -1); do cp "$f" "$here/"; done
fi
echo "run_speeds: gate.png, gate.json and the 1 m/s run's output in $here; runs in $out"
