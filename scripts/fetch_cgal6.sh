#!/usr/bin/env bash
# Fetches Debian 13 (trixie)'s libcgal-dev (CGAL 6, header-only) and unpacks it into
# the build tree, without installing anything system-wide: apt runs with a private
# configuration (its own sources list, state, lists and cache under build-cgal6/apt/,
# no lock on the system's apt), downloads the .deb, and dpkg-deb -x extracts it into
# build-cgal6/cgal6/. Idempotent: an extracted tree is reused.
# Prints the CGAL_DIR to configure with (its last line of output on stdout).
# Usage: scripts/fetch_cgal6.sh [BUILD_DIR]   (default: build-cgal6)
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir="$(realpath -m "${1:-build-cgal6}")"
apt_dir="$build_dir/apt"
root="$build_dir/cgal6"
cgal_dir="$root/usr/lib/x86_64-linux-gnu/cmake/CGAL"
version_header="$root/usr/include/CGAL/version.h"
expected_version="6.0.1"

version_of() { sed -n 's/^#define CGAL_VERSION \([0-9.]*\).*/\1/p' "$1"; }

if [ -f "$root/.extracted" ] && [ -f "$cgal_dir/CGALConfig.cmake" ]; then
  echo "CGAL $(version_of "$version_header") already extracted in $root" >&2
  echo "$cgal_dir"
  exit 0
fi

# The mirror the machine's own apt configuration uses (deb822 or one-line format).
mirror=""
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  mirror="$(awk '/^URIs:/ { for (i = 2; i <= NF; ++i) if ($i ~ /\/debian\/?$/) { print $i; exit } }' "$f")"
  [ -n "$mirror" ] && break
done
if [ -z "$mirror" ]; then
  mirror="$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
            awk '$1 == "deb" { for (i = 2; i <= NF; ++i) if ($i ~ /^https?:.*\/debian\/?$/) { print $i; exit } }')"
fi
mirror="${mirror:-http://deb.debian.org/debian}"

# trixie's Release file is signed by the trixie archive and release keys, which
# bookworm's debian-archive-keyring (2023.3+deb12u2) already ships: apt verifies the
# suite's signature against them as it does for the system's own sources.
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
for k in debian-archive-trixie-automatic.gpg debian-archive-trixie-stable.gpg; do
  if [ ! -f "/usr/share/keyrings/$k" ]; then
    echo "fetch_cgal6.sh: /usr/share/keyrings/$k is missing (debian-archive-keyring too old to verify trixie)" >&2
    exit 1
  fi
done

mkdir -p "$apt_dir"/{etc/sources.list.d,etc/preferences.d,state/lists/partial,cache/archives/partial,debs}
cat > "$apt_dir/etc/sources.list" <<EOF
deb [signed-by=$keyring] $mirror trixie main
EOF
: > "$apt_dir/state/status"   # an empty dpkg status: no installed package is looked at
apt_opts=(
  -o Dir::Etc::SourceList="$apt_dir/etc/sources.list"
  -o Dir::Etc::SourceParts="$apt_dir/etc/sources.list.d"
  -o Dir::Etc::Preferences="$apt_dir/etc/preferences"
  -o Dir::Etc::PreferencesParts="$apt_dir/etc/preferences.d"
  -o Dir::State="$apt_dir/state"
  -o Dir::State::Lists="$apt_dir/state/lists"
  -o Dir::State::status="$apt_dir/state/status"
  -o Dir::Cache="$apt_dir/cache"
  -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=
  -o Debug::NoLocking=1
  -o APT::Architecture=amd64 -o APT::Architectures::=amd64
  -o Acquire::Languages=none
)
# as root, apt downloads as the user _apt, who may not write in the build tree
if [ "$(id -u)" -eq 0 ]; then apt_opts+=(-o APT::Sandbox::User=root); fi
echo "fetch_cgal6.sh: apt-get update (trixie at $mirror, state in $apt_dir)" >&2
apt-get "${apt_opts[@]}" -qq update >&2
(cd "$apt_dir/debs" && rm -f libcgal-dev_*.deb &&
 apt-get "${apt_opts[@]}" -qq download libcgal-dev >&2)
deb="$(ls "$apt_dir"/debs/libcgal-dev_*.deb)"
echo "fetch_cgal6.sh: extracting $(basename "$deb")" >&2
rm -rf "$root"
dpkg-deb -x "$deb" "$root"

version="$(version_of "$version_header")"
case "$version" in
  "$expected_version") ;;
  6.*) echo "fetch_cgal6.sh: warning: $deb holds CGAL $version; the suite was checked with $expected_version" >&2 ;;
  *) echo "fetch_cgal6.sh: $deb holds CGAL '$version', expected $expected_version" >&2; exit 1 ;;
esac
[ -f "$cgal_dir/CGALConfig.cmake" ] || { echo "fetch_cgal6.sh: no CGALConfig.cmake in $cgal_dir" >&2; exit 1; }
touch "$root/.extracted"
echo "CGAL $version extracted in $root" >&2
echo "$cgal_dir"
