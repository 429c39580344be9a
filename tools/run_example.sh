#!/bin/bash
# The README's "run" command: build (installing what is missing), run an example under MPI on all
# cores, and leave its pictures, dumps, plot (PNG) and numbers (JSON) in the example's directory
# (python3 -m sph_soil run-example: tools/sph_soil/examples.py says what each example leaves).
#
#   tools/run_example.sh [example-name] [extra lmp arguments, e.g. -var d 0.001]
#       default example: aluminium_bars (Bui 2008's experiment, 2 mm spacing, ~3 min on 2 cores)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/tools/build_dir.sh"
example=${1:-aluminium_bars}
shift || true

bash "$root/tools/build.sh"
PYTHONPATH=$root/tools /usr/bin/python3 -m sph_soil run-example --lmp "$build/lmp" --np "$(nproc)" \
  "$example" -- "$@"
