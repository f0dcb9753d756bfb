#!/bin/bash
# Install what lithostress needs from Debian's archive, if it is missing.
# Idempotent: does nothing when every package is already installed.
set -euo pipefail
packages=(libdeal.ii-dev libsuitesparse-dev libopenblas0-serial openmpi-bin cmake make g++ numdiff python3 python3-numpy python3-scipy python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "lithostress: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
