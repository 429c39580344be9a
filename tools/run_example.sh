#!/bin/bash
# The README's "run" command: build (installing what is missing) and run the main example
# under MPI on all cores, leaving its pictures and dumps in the example's directory.
#
#   tools/run_example.sh [example-name]     (default: atom_style)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
example=${1:-atom_style}
dir=$root/examples/$example
[ -f "$dir/in.$example" ] || { echo "run_example: no $dir/in.$example" >&2; exit 1; }

bash "$root/tools/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$dir"
np=$(nproc)
start=$(date +%s)
mpirun -np "$np" "$build/lmp" -in "in.$example" -log "log.$example.run"
echo "run_example: $example done in $(( $(date +%s) - start )) s on $np ranks; output in $dir:"
ls -1 "$dir" | grep -v '^in\.' | sed 's/^/  /'
