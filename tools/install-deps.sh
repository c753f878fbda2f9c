#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages this project needs, if any are missing, plus any package
# names given as arguments (CI adds clang). Works as root or through sudo; does nothing when
# everything is already there.
set -euo pipefail

packages=(cmake make g++ pkg-config catch2 libstb-dev bubblewrap procps libtinyobjloader-dev
          libgif-dev libglm-dev nlohmann-json3-dev "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "Installing: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "error: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
