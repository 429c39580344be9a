# Sourced by the build, test and example scripts: the build directory for the LAMMPS selected by
# SPH_SOIL_LAMMPS (build/ for the default, newest one; build-<release>/ for another), unless
# BUILD_DIR is set.
case "${SPH_SOIL_LAMMPS:-newest}" in
  newest) build=${BUILD_DIR:-$root/build};;
  *) build=${BUILD_DIR:-$root/build-$SPH_SOIL_LAMMPS};;
esac
