#!/bin/bash
# Install the Debian packages SPH_SOIL needs to build, test and run its examples,
# only those that are missing (apt-get update runs only if something must be installed).
set -euo pipefail

packages=(cmake ninja-build g++ make pkg-config dpkg-dev ccache
          libopenmpi-dev openmpi-bin libeigen3-dev libpng-dev libjpeg-dev zlib1g-dev gzip
          libgtest-dev libgmock-dev python3-numpy python3-matplotlib python3-pytest)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup_deps: installing ${missing[*]}"
sudo=()
[ "$(id -u)" -eq 0 ] || sudo=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
