#!/usr/bin/env bash
# Installs Patina's build and test dependencies from Debian 12 packages. Safe to re-run:
# it asks apt only for what is missing. With --sanitizers, also clang with its sanitizer and
# libFuzzer runtimes and llvm-symbolizer (scripts/sanitize.sh, scripts/fuzz.sh).
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libglfw3-dev libglm-dev libimgui-dev libtinygltf-dev libstb-dev nlohmann-json3-dev zlib1g-dev
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgles-dev
  libcli11-dev libgtest-dev libbenchmark-dev libopenexr-dev
  # Cairo (with fontconfig) draws the charts and the captions in DejaVu Sans below.
  libcairo2-dev
  # Draco decodes KHR_draco_mesh_compression's meshes (engine/gltf/draco.cpp).
  libdraco-dev
  # meshoptimizer decodes EXT_meshopt_compression's buffer views (engine/gltf/meshopt.cpp),
  # libwebp EXT_texture_webp's images (engine/gltf/images.cpp).
  libmeshoptimizer-dev libwebp-dev
  # Embree 3 casts the ground truth's shadow and occlusion rays (engine/reference/ray_caster.cpp).
  libembree-dev
  xvfb xdotool
  # The editor's UI font, the captions' and the charts' (DejaVu Sans, read at run time), Droid
  # Sans Fallback for the CJK characters DejaVu lacks (fontconfig finds it for a caption), and
  # xdg-open, which shows the screenshots' folder in the desktop's file manager.
  fonts-dejavu-core fonts-droid-fallback xdg-utils
  # Blender's eight CC0 HDRIs (/usr/share/blender/datafiles/studiolights/world/*.exr), which the
  # environment tests read: real files from a real writer.
  blender-data
  # assimp's glTF 2.0 test models (/usr/share/assimp/models/glTF2), which the glTF model tests
  # read: real files from other writers, broken ones among them.
  assimp-testmodels
)
# Clang 16, the first to take the shaders' C++ (parenthesized aggregate initialization, P0960);
# libclang-rt-16-dev holds libFuzzer and the ASan/UBSan runtimes (clang-16 only recommends it);
# llvm-16 has the llvm-symbolizer that turns sanitizer reports into file:line.
[ "${1:-}" = --sanitizers ] && packages+=(clang-16 libclang-rt-16-dev llvm-16)
# Node.js runs the glTF validator of the tests; one from elsewhere (nodesource) will do.
command -v node >/dev/null && command -v npm >/dev/null || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
else
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The Khronos glTF-Validator (npm), which the export tests run, in third_party/gltf-validator
# (ignored by git). Pinned: nothing to do when that version is there.
validator_version=2.0.0-dev.3.10
validator_dir="$(cd "$(dirname "$0")/.." && pwd)/third_party/gltf-validator"
installed=$(node -p "require('$validator_dir/node_modules/gltf-validator/package.json').version" 2>/dev/null || true)
if [ "$installed" = "$validator_version" ]; then
  echo "setup: gltf-validator $validator_version present"
else
  echo "setup: installing gltf-validator $validator_version with npm"
  npm install --prefix "$validator_dir" --no-save --no-audit --no-fund --loglevel=error \
    "gltf-validator@$validator_version"
fi
