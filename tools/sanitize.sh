#!/bin/bash
# Build LAMMPS with SPH_SOIL and its tests under AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc's -fsanitize=address,undefined) in build-sanitize/, and run the whole test suite there.
# Any sanitizer report fails the test that triggered it (UBSan does not recover; ASan stops at
# the first error). Leak detection is off: Open MPI keeps its allocations until exit.
#
#   tools/sanitize.sh [ctest arguments, e.g. -R test_parallel]
#
# Environment: as tools/build.sh (SPH_SOIL_LAMMPS selects the LAMMPS; BUILD_DIR overrides the
# build directory, default build-sanitize).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
export BUILD_DIR=${BUILD_DIR:-$root/build-sanitize}

flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
bash "$root/tools/build.sh" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS=$flags" \
  "-DCMAKE_C_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=$flags" "-DCMAKE_SHARED_LINKER_FLAGS=$flags" \
  "-DSPH_SOIL_OPTIMIZE=-O1;-g" -DSPH_SOIL_TEST_TIMEOUT_FACTOR=4

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:print_summary=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$BUILD_DIR"
start=$(date +%s)
ctest --output-on-failure -j "$(nproc)" "$@"
echo "sanitize: tests done in $(( $(date +%s) - start )) s"
