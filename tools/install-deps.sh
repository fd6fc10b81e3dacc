#!/usr/bin/env bash
# Installs the Debian 12 packages snell builds, tests and benchmarks with; only the missing ones.
# Run as root (or with sudo available). Nothing is downloaded except through apt.
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libembree-dev libtbb-dev libopenimageio-dev openimageio-tools libopenexr-dev libassimp-dev
  libpng-dev libfreetype-dev
  libcli11-dev libfmt-dev libgtest-dev libgmock-dev libbenchmark-dev libopenmpi-dev openmpi-bin
  zlib1g-dev libsdl2-dev xvfb xauth
  povray povray-includes povray-examples python3 python3-numpy python3-pil python3-jsonschema hyperfine
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
((${#missing[@]} == 0)) && exit 0
echo "install-deps: installing ${missing[*]}"
sudo=""
if ((EUID != 0)); then
  command -v sudo >/dev/null || { echo "install-deps: run as root to install: ${missing[*]}" >&2; exit 1; }
  sudo=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
