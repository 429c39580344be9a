#!/bin/bash
# Fetch and unpack Debian's `lammps` source package (20220106 = stable 29Sep2021 update 2)
# into DEST, using apt's source mechanism with a *private* sources list and lists directory
# derived from the system's Debian entries. The system's apt configuration is not touched.
#
#   tools/fetch_lammps_source.sh DEST [WORKDIR]
#
# DEST must not contain '~' (Ninja loses header dependencies on such paths); the default
# directory name that dpkg-source would choose (lammps-0~2022...) is therefore not used.
set -euo pipefail

dest=${1:?usage: fetch_lammps_source.sh DEST [WORKDIR]}
work=${2:-"$(dirname "$dest")/apt-private"}
want_version_prefix=${SPH_SOIL_LAMMPS_DEBIAN_VERSION:-20220106}

case "$dest" in *'~'*) echo "fetch_lammps_source: DEST '$dest' contains '~'" >&2; exit 1;; esac
if [ -f "$dest/src/version.h" ]; then
  echo "fetch_lammps_source: $dest already holds a LAMMPS source tree"; exit 0
fi
for tool in apt-get dpkg-source; do
  command -v "$tool" >/dev/null || { echo "fetch_lammps_source: '$tool' not found (install apt and dpkg-dev)" >&2; exit 1; }
done

mkdir -p "$work/sources.list.d" "$work/lists/partial" "$work/cache/archives/partial" "$work/download"
rm -f "$work/sources.list.d/"*

# Derive deb-src entries from the system's Debian 'deb' entries (one-line and deb822 formats).
n=0
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] || continue
  grep -E '^[[:space:]]*deb[[:space:]]' "$f" | grep -i debian | sed -E 's/^[[:space:]]*deb[[:space:]]/deb-src /' \
    >> "$work/sources.list.d/private.list" || true
done
[ -s "$work/sources.list.d/private.list" ] && n=1 || rm -f "$work/sources.list.d/private.list"
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  grep -qi 'debian' "$f" || continue
  n=$((n + 1))
  sed -E 's/^Types:.*\bdeb\b.*$/Types: deb-src/' "$f" > "$work/sources.list.d/private-$n.sources"
done
if [ "$n" -eq 0 ]; then
  echo "fetch_lammps_source: no Debian entries found in /etc/apt to derive deb-src entries from" >&2
  exit 1
fi

apt_opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$work/sources.list.d"
          -o "Dir::State::Lists=$work/lists" -o "Dir::Cache=$work/cache"
          -o "Debug::NoLocking=1" -o "APT::Sandbox::User=root")
echo "fetch_lammps_source: updating the private source lists in $work"
apt-get "${apt_opts[@]}" -qq update

version=$(apt-cache "${apt_opts[@]}" showsrc lammps 2>/dev/null | sed -n 's/^Version: //p' \
          | grep "^$want_version_prefix" | sort -V | tail -n 1 || true)
if [ -z "$version" ]; then
  echo "fetch_lammps_source: Debian's sources offer no lammps version starting with $want_version_prefix" >&2
  exit 1
fi
echo "fetch_lammps_source: fetching lammps=$version"
(cd "$work/download" && apt-get "${apt_opts[@]}" -qq source --download-only "lammps=$version")

dsc=$(ls "$work/download"/lammps_*.dsc | head -n 1)
tmp="$dest.unpack.$$"
rm -rf "$tmp"
dpkg-source --no-check -x "$dsc" "$tmp" > "$work/dpkg-source.log"
grep -q '"29 Sep 2021"' "$tmp/src/version.h" || {
  echo "fetch_lammps_source: unexpected LAMMPS version in $tmp/src/version.h" >&2; exit 1; }
mv "$tmp" "$dest"
# dpkg-source leaves a link to the upstream tarball beside the tree
rm -f "$(dirname "$dest")"/lammps_*.orig.tar.*
rm -rf "$work/download"
echo "fetch_lammps_source: LAMMPS source ready in $dest"
