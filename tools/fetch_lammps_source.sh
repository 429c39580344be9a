#!/bin/bash
# Fetch and unpack the LAMMPS source of one of Debian's `lammps` source packages, through apt's
# source mechanism with a *private* sources list and lists directory: the system's apt
# configuration is not touched.
#
#   tools/fetch_lammps_source.sh [--release NAME] [--cache DIR] [--print-dir FILE]
#
# --release NAME  which LAMMPS (default: $SPH_SOIL_LAMMPS, else `newest`):
#     newest     Debian's newest: 4Jul2026 from the unstable suite; if that suite cannot be
#                reached, 4Feb2025 from Debian 13 (trixie)
#     4Jul2026   lammps 20260704 (unstable)
#     4Feb2025   lammps 20250204 (trixie, Debian 13)
#     29Sep2021  lammps 20220106 = stable 29Sep2021 update 2 (bookworm, Debian 12)
# --cache DIR     where trees are unpacked and kept, as DIR/lammps-<yyyymmdd> (default:
#                 $SPH_SOIL_CACHE_DIR, else ~/.cache/sph_soil). The path must not contain '~'
#                 (Ninja loses header dependencies on such paths), so the directory name that
#                 dpkg-source would choose (lammps-0~2022...) is not used.
# --print-dir FILE  write the tree's path into FILE (for CMake)
#
# A tree already in the cache is used without any network access. SPH_SOIL_DEBIAN_MIRROR
# overrides the Debian mirror (default: the one of the system's apt entries). What is unpacked is the
# upstream tarball of Debian's source package (its *.orig.tar.*), checked against the SHA256
# of Debian's signed source index. Debian's packaging patches are not applied: they are for
# Debian's own binary packages (one hard-codes /usr/share/lammps/potentials in place of the
# LAMMPS_POTENTIALS environment variable), and some mirrors serve only the tarball.
set -euo pipefail

release=${SPH_SOIL_LAMMPS:-newest}
cache=${SPH_SOIL_CACHE_DIR:-$HOME/.cache/sph_soil}
print_dir=
while [ $# -gt 0 ]; do
  case "$1" in
    --release) release=$2; shift 2;;
    --cache) cache=$2; shift 2;;
    --print-dir) print_dir=$2; shift 2;;
    *) echo "fetch_lammps_source: unknown argument '$1' (see the script's header)" >&2; exit 2;;
  esac
done

# release -> "suite debian-version-prefix version.h-date"; one line per supported release
release_info() {
  case "$1" in
    4Jul2026)  echo "unstable 20260704 4 Jul 2026";;
    4Feb2025)  echo "trixie 20250204 4 Feb 2025";;
    29Sep2021) echo "bookworm 20220106 29 Sep 2021";;
    *) return 1;;
  esac
}
case "$release" in
  newest) candidates=(4Jul2026 4Feb2025);;
  *) release_info "$release" >/dev/null || {
       echo "fetch_lammps_source: unknown release '$release' (newest, 4Jul2026, 4Feb2025 or 29Sep2021)" >&2
       exit 2; }
     candidates=("$release");;
esac
case "$cache" in *'~'*) echo "fetch_lammps_source: cache directory '$cache' contains '~'" >&2; exit 1;; esac

finish() {    # tree
  echo "fetch_lammps_source: LAMMPS source in $1 ($(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"/\1/p' "$1/src/version.h"))"
  [ -z "$print_dir" ] || printf '%s\n' "$1" > "$print_dir"
  exit 0
}

# A private sources list with deb-src entries for the Debian archive of the system's entries,
# made on first need (a tree already in the cache needs no network).
apt_ready=0
setup_apt() {
  [ "$apt_ready" -eq 1 ] && return
  for tool in apt-get apt-cache; do
    command -v "$tool" >/dev/null || { echo "fetch_lammps_source: '$tool' not found" >&2; exit 1; }
  done
  helper=/usr/lib/apt/apt-helper
  [ -x "$helper" ] || { echo "fetch_lammps_source: $helper not found" >&2; exit 1; }
  work=$cache/apt-private
  mkdir -p "$work/sources.list.d" "$work/lists/partial" "$work/cache/archives/partial"
  rm -f "$work/sources.list.d/"*
  mirror=${SPH_SOIL_DEBIAN_MIRROR:-$(grep -hoE '^[[:space:]]*(deb|URIs:)[[:space:]]+[^ ]*debian[^ ]*' \
           /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources \
           2>/dev/null | awk '{print $2}' | grep -v -- '-security' | head -n 1 || true)}
  mirror=${mirror:-http://deb.debian.org/debian}
  keyring=/usr/share/keyrings/debian-archive-keyring.gpg
  apt_opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$work/sources.list.d"
            -o "Dir::State::Lists=$work/lists" -o "Dir::Cache=$work/cache"
            -o "Debug::NoLocking=1" -o "APT::Sandbox::User=root")
  apt_ready=1
}

# Fetch and unpack release $1 into the cache; returns 1 if its suite cannot be reached or does
# not offer it (the caller tries the next candidate), exits on any other failure.
fetch() {
  local suite prefix date version line uri file size hash download tree tmp top
  read -r suite prefix date <<< "$(release_info "$1")"
  setup_apt
  printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: %s\n' \
    "$mirror" "$suite" "$keyring" > "$work/sources.list.d/debian-src.sources"
  rm -rf "$work/lists"; mkdir -p "$work/lists/partial"
  echo "fetch_lammps_source: reading Debian's '$suite' source index from $mirror"
  if ! apt-get "${apt_opts[@]}" -qq update 2> "$work/update.log" \
     || grep -qE '^(E:|W: Failed)' "$work/update.log"; then
    echo "fetch_lammps_source: suite '$suite' not reachable:" >&2; sed 's/^/  /' "$work/update.log" >&2
    return 1
  fi
  version=$(apt-cache "${apt_opts[@]}" showsrc lammps 2>/dev/null | sed -n 's/^Version: //p' \
            | grep "^$prefix" | sort -V | tail -n 1 || true)
  if [ -z "$version" ]; then
    echo "fetch_lammps_source: '$suite' offers no lammps source starting with $prefix" >&2
    return 1
  fi
  # the upstream tarball's address and checksum, from apt's verified index
  download=$work/download; rm -rf "$download"; mkdir -p "$download"
  line=$(cd "$download" && apt-get "${apt_opts[@]}" -qq --print-uris source "lammps=$version" \
         | grep -E "\.orig\.tar\.[a-z0-9]+' " | head -n 1)
  read -r uri file size hash <<< "$line"
  uri=${uri//\'/}
  echo "fetch_lammps_source: fetching lammps $version: $file ($((size / 1048576)) MiB)"
  # (the download runs unsandboxed as root: the private cache is not readable by _apt)
  if ! "$helper" download-file "$uri" "$download/$file" "$hash" > "$work/download.log" 2>&1 \
     || [ ! -f "$download/$file" ]; then
    echo "fetch_lammps_source: download of $uri failed:" >&2; sed 's/^/  /' "$work/download.log" >&2
    exit 1
  fi
  tree=$cache/lammps-$prefix
  tmp=$tree.unpack.$$
  rm -rf "$tmp"; mkdir -p "$tmp"
  tar -xf "$download/$file" -C "$tmp"
  rm -rf "$download"
  # some tarballs hold one top directory, others the tree itself
  if [ ! -d "$tmp/src" ] && [ "$(ls -A "$tmp" | wc -l)" -eq 1 ]; then
    top=$(ls -A "$tmp"); mv "$tmp/$top" "$tmp.top"; rmdir "$tmp"; mv "$tmp.top" "$tmp"
  fi
  grep -q "\"$date\"" "$tmp/src/version.h" || {
    echo "fetch_lammps_source: $file does not hold LAMMPS $date (see $tmp/src/version.h)" >&2; exit 1; }
  rm -rf "$tree"; mv "$tmp" "$tree"
  finish "$tree"
}

# in order of preference: the tree in the cache, else fetched; else the next candidate
for r in "${candidates[@]}"; do
  read -r _ prefix _ <<< "$(release_info "$r")"
  [ -f "$cache/lammps-$prefix/src/version.h" ] && finish "$cache/lammps-$prefix"
  fetch "$r" || continue
done
echo "fetch_lammps_source: no LAMMPS source could be fetched for '$release'" >&2
exit 1
