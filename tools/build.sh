#!/bin/bash
# Configure and build LAMMPS with the SPH_SOIL package (lmp, liblammps, tests, tools).
# Installs missing Debian packages first; fetches Debian's LAMMPS source on first use.
#
#   tools/build.sh [extra cmake arguments, e.g. -DLAMMPS_SOURCE_DIR=/path/to/lammps]
#
# Environment:
#   SPH_SOIL_LAMMPS     which of Debian's LAMMPS sources to build against: newest (default:
#                       4Jul2026, else 4Feb2025), 4Jul2026, 4Feb2025 or 29Sep2021
#   BUILD_DIR           default: build for the newest LAMMPS, build-<release> for another
#   JOBS                default: number of cores
#   SPH_SOIL_CACHE_DIR  where fetched LAMMPS sources are kept (default ~/.cache/sph_soil)
#   LAMMPS_SOURCE_DIR   use this LAMMPS tree instead of fetching one
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/tools/build_dir.sh"
jobs=${JOBS:-$(nproc)}

bash "$root/tools/setup_deps.sh"

# ccache keyed on paths relative to the checkout: a fresh clone reuses earlier compilations.
export CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=true

args=("$@")
[ -n "${SPH_SOIL_LAMMPS:-}" ] && args+=("-DSPH_SOIL_LAMMPS=$SPH_SOIL_LAMMPS")
[ -n "${SPH_SOIL_CACHE_DIR:-}" ] && args+=("-DSPH_SOIL_CACHE_DIR=$SPH_SOIL_CACHE_DIR")
[ -n "${LAMMPS_SOURCE_DIR:-}" ] && args+=("-DLAMMPS_SOURCE_DIR=$LAMMPS_SOURCE_DIR")
if [ ! -f "$build/build.ninja" ] || [ ${#args[@]} -gt 0 ]; then
  cmake -S "$root" -B "$build" -G Ninja "${args[@]}"
fi
start=$(date +%s)
cmake --build "$build" -j "$jobs"
echo "build: done in $(( $(date +%s) - start )) s; lmp is $build/lmp"
