#!/bin/bash
# Build everything and run all tests (GoogleTest under ctest, at 1 and 2 MPI ranks).
# This is the README's test command and what CI (.ci/run) runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/tools/build_dir.sh"

bash "$root/tools/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
