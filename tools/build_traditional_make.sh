#!/bin/bash
# Build SPH_SOIL into a LAMMPS source tree with LAMMPS's own traditional make (no CMake), the
# way a user drops the package into a tree of their own, then run the short aluminium-bar
# example with the resulting lmp_mpi and compare it with the reference logs.
#
#   tools/build_traditional_make.sh [--lammps DIR] [--no-run]
#
# --lammps DIR  build in this LAMMPS tree (its src/ receives SPH_SOIL and the package files).
#               Default: a scratch copy of the fetched tree of SPH_SOIL_LAMMPS (see
#               tools/build.sh) in <build dir>/traditional_make, so that the cached tree, which
#               the CMake build uses, stays clean (LAMMPS's CMake refuses a tree in which make
#               has installed packages).
# --no-run      build only.
#
# What it does in <tree>/src, i.e. the recipe of README.md:
#   cp -r SPH_SOIL <tree>/src/
#   make yes-sph_soil yes-rigid [yes-graphics]            # GRAPHICS holds dump image after 4Feb2025
#   make mpi LMP_INC="... -DLAMMPS_PNG -DLAMMPS_JPEG" JPG_LIB="-lpng -ljpeg"
# The compiler runs through ccache when it is installed (CC="ccache mpicxx").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/tools/build_dir.sh"
tree=
run=1
while [ $# -gt 0 ]; do
  case "$1" in
    --lammps) tree=$(cd "$2" && pwd); shift 2;;
    --no-run) run=0; shift;;
    *) echo "build_traditional_make: unknown argument '$1'" >&2; exit 2;;
  esac
done

bash "$root/tools/setup_deps.sh"
if [ -z "$tree" ]; then
  cache=${SPH_SOIL_CACHE_DIR:-$HOME/.cache/sph_soil}
  bash "$root/tools/fetch_lammps_source.sh" --release "${SPH_SOIL_LAMMPS:-newest}" --cache "$cache" \
    --print-dir "$build.source_dir"
  source_tree=$(cat "$build.source_dir"); rm -f "$build.source_dir"
  tree=$build/traditional_make/lammps
  mkdir -p "$tree"
  # only src/ is needed; rsync-like refresh that keeps make's objects between runs
  cp -a -u "$source_tree/src" "$tree/"
fi
[ -f "$tree/src/Makefile" ] || { echo "build_traditional_make: $tree/src/Makefile not found" >&2; exit 1; }

cd "$tree/src"
# an earlier copy's files leave src/ first (files renamed since would otherwise stay behind)
[ -d SPH_SOIL ] && make no-sph_soil > /dev/null
rm -rf SPH_SOIL
cp -r "$root/src/SPH_SOIL" .
packages=(sph_soil rigid)
[ -d GRAPHICS ] && packages+=(graphics)
for p in "${packages[@]}"; do make "yes-$p" > /dev/null; done
# a second run updates the copies of changed package files
make pu > /dev/null
cc=mpicxx
command -v ccache >/dev/null && { cc="ccache mpicxx"; export CCACHE_BASEDIR=$tree CCACHE_NOHASHDIR=true; }
start=$(date +%s)
make -j "${JOBS:-$(nproc)}" mpi CC="$cc" \
  LMP_INC="-DLAMMPS_GZIP -DLAMMPS_MEMALIGN=64 -DLAMMPS_PNG -DLAMMPS_JPEG" JPG_LIB="-lpng -ljpeg" \
  > "$tree/make.log" 2>&1 || { tail -n 30 "$tree/make.log"; echo "build_traditional_make: make failed (log: $tree/make.log)" >&2; exit 1; }
echo "build_traditional_make: $tree/src/lmp_mpi built in $(( $(date +%s) - start )) s ($(./lmp_mpi -h | sed -n 's/.*Simulator - //p' | head -n 1))"
./lmp_mpi -h | grep -q 'sph_soil/set' || { echo "build_traditional_make: lmp_mpi lacks the SPH_SOIL styles" >&2; exit 1; }

if [ "$run" -eq 1 ]; then
  # the tools' runner sets LAMMPS_POTENTIALS to the package's potentials/, which the traditional
  # make knows nothing of, and Open MPI's permission to run as root
  PYTHONPATH=$root/tools /usr/bin/python3 -m sph_soil regression --lmp "$tree/src/lmp_mpi" \
    --example aluminium_bars --np 2 --workdir "$tree/regression_aluminium_bars_np2"
fi
