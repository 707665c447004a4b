#!/usr/bin/env bash
# Installs Patina's build and test dependencies from Debian 12 packages. Safe to re-run:
# it asks apt only for what is missing.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libglfw3-dev libglm-dev libimgui-dev libtinygltf-dev libstb-dev nlohmann-json3-dev
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgles-dev
  libcli11-dev libgtest-dev libbenchmark-dev
  xvfb xdotool
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
