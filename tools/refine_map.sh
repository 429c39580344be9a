#!/bin/bash
# The refinement-parameter map (doc/refinement_parameters.rst): CSV, summary JSON and figure.
#   tools/refine_map.sh [extra sph_soil_refine_map options, e.g. --ra 1.3 or --dimension 3]
# Builds the tool if needed; writes doc/refine_map.csv, doc/refine_map.json, doc/img/refine_map.png.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
[ -x "$build/sph_soil_refine_map" ] || bash "$root/tools/build.sh"
mkdir -p "$root/doc/img"
"$build/sph_soil_refine_map" --csv "$root/doc/refine_map.csv" --json "$root/doc/refine_map.json" "$@"
ra=1.2
args=("$@")
for ((k = 0; k < ${#args[@]}; k++)); do [ "${args[$k]}" = --ra ] && ra=${args[$((k + 1))]}; done
/usr/bin/python3 "$root/tools/plot_refine_map.py" "$root/doc/refine_map.csv" "$root/doc/img/refine_map.png" --ra "$ra"
echo "refine_map: doc/refine_map.csv, doc/refine_map.json, doc/img/refine_map.png"
