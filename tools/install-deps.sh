#!/usr/bin/env bash
# Installs the Debian 12 packages fragpath needs to build, test and render; does nothing when all are there.
set -euo pipefail
packages=(
  cmake make g++ pkg-config python3-glad git
  libosmesa6-dev libegl-dev libglm-dev libtinyobjloader-dev nlohmann-json3-dev libstb-dev libtinyexr-dev libtinygltf-dev libgtest-dev
  libdraco-dev libmeshoptimizer-dev
  libglfw3-dev libimgui-dev xvfb xauth clang libclang-rt-14-dev
  gnuplot-nox
  python3-numpy  # Blender's glTF importer needs it (tools/race_cycles.py --scene gltf)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "Installing missing packages: ${missing[*]}"
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
