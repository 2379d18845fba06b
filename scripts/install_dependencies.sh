#!/usr/bin/env bash
# Installs, with apt, the Debian packages the build needs and that are missing.
# Usage: scripts/install_dependencies.sh [extra packages...]
set -euo pipefail

packages=(cmake make g++ ccache libcgal-dev libcgal-demo libboost-dev libgmp-dev libmpfr-dev libtbb-dev nlohmann-json3-dev strace "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=""
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
