#!/bin/bash
# The README's "run" command: build (installing what is missing), run the main example under
# MPI on all cores, and leave its pictures, dumps and comparison with the experiment in the
# example's directory.
#
#   tools/run_example.sh [example-name] [extra lmp arguments, e.g. -var d 0.001]
#       default example: aluminium_bars (Bui 2008's experiment, 2 mm spacing, ~3 min on 2 cores)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/tools/build_dir.sh"
example=${1:-aluminium_bars}
shift || true
dir=$root/examples/$example
[ -f "$dir/in.$example" ] || { echo "run_example: no $dir/in.$example" >&2; exit 1; }

bash "$root/tools/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$dir"
np=$(nproc)
start=$(date +%s)
mpirun -np "$np" "$build/lmp" -in "in.$example" -log "log.$example.run" "$@"
seconds=$(( $(date +%s) - start ))
echo "run_example: $example done in $seconds s on $np ranks"

if [ "$example" = aluminium_bars ]; then
  /usr/bin/python3 "$root/tools/validate_aluminium_bars.py" --dir "$dir" --wall-seconds "$seconds" \
    --json "$dir/validation.json" --plot "$dir/validation.png"
fi
echo "run_example: output in $dir:"
ls -1 "$dir" | grep -E '^(frame|dump|validation|log\..*\.run)' | sed 's/^/  /'
