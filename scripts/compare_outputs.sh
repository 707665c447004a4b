#!/usr/bin/env bash
# Renders a fixed set of inputs through every command of a patina binary, so that two builds
# (before and after a change meant to keep behaviour) can be compared byte for byte.
#
#   bash scripts/compare_outputs.sh run PATINA OUT_DIR     writes the outputs into OUT_DIR
#   bash scripts/compare_outputs.sh diff DIR_A DIR_B       lists the files that differ
#
# The inputs: the default scene's sphere, a torus and a glTF model (the torus exported as .glb
# by the binary under test) through the single, multi and specialised paths at 1 and 4 samples,
# as PNG and PFM; compare (with --diff); a sheet of every preset; probe on the CPU and the GPU;
# lobe; export as .gltf and .glb. The scenes are the default scene as a version 1 file, which
# every later version still reads, so that builds before and after a format change compare.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

default_scene_v1() {
  cat <<'EOF'
{
  "format": "patina-scene",
  "version": 1,
  "mesh": "sphere",
  "material": {
    "format": "patina-material",
    "version": 1,
    "name": "terracotta",
    "baseColor": [0.8, 0.25, 0.15],
    "roughness": 0.4,
    "specular": 0.5,
    "metallic": 0.0
  },
  "camera": {
    "position": [0.0, 0.6, 3.4],
    "target": [0.0, 0.0, 0.0],
    "fovYDegrees": 45.0
  },
  "lights": [
    {
      "type": "point",
      "name": "warm key",
      "enabled": true,
      "color": [1.0, 0.78, 0.55],
      "intensity": 16.0,
      "position": [2.2, 2.0, 2.4],
      "radius": 12.0,
      "attenuation": [1.0, 0.0, 1.0]
    },
    {
      "type": "directional",
      "name": "cool fill",
      "enabled": true,
      "color": [0.55, 0.7, 1.0],
      "intensity": 2.0,
      "direction": [1.0, -0.35, -0.6]
    },
    {
      "type": "hemisphere",
      "name": "sky",
      "enabled": true,
      "color": [1.0, 1.0, 1.0],
      "intensity": 0.8,
      "sky": [0.22, 0.3, 0.45],
      "ground": [0.12, 0.09, 0.06]
    }
  ],
  "display": {
    "exposure": 0.0,
    "tonemap": "none",
    "background": [0.02, 0.02, 0.025]
  }
}
EOF
}

run() {
  local patina out
  patina=$(realpath "$1")
  out=$2
  mkdir -p "$out/inputs"
  out=$(realpath "$out")
  local in=$out/inputs
  default_scene_v1 >"$in/sphere.json"
  sed 's/"mesh": "sphere"/"mesh": "torus"/' "$in/sphere.json" >"$in/torus.json"
  "$patina" export --mesh torus --out "$in/model.glb" >/dev/null
  sed 's/"mesh": "sphere"/"mesh": "model.glb"/' "$in/sphere.json" >"$in/model.json"
  local scene passes msaa
  for scene in sphere torus model; do
    for passes in single multi specialised; do
      for msaa in 1 4; do
        "$patina" render --scene "$in/$scene.json" --width 160 --height 120 --passes "$passes" \
          --msaa "$msaa" --out "$out/render-$scene-$passes-$msaa.png" \
          --hdr "$out/render-$scene-$passes-$msaa.pfm" >/dev/null
      done
    done
  done
  "$patina" render --width 1920 --height 1080 --msaa 8 --out "$out/render-1080p-8.png" >/dev/null
  "$patina" compare "$here/presets/gold.json" "$here/presets/copper.json" --width 128 --height 96 \
    --out "$out/compare.png" --diff >/dev/null
  "$patina" sheet "$here"/presets/*.json --size 96 --columns 6 --out "$out/sheet.png" >/dev/null
  printf 'px,py,pz,nx,ny,nz,vx,vy,vz\n' >"$in/probe.csv"
  local t
  for t in 0 1 2 3 4 5 6 7; do
    awk -v t="$t" 'BEGIN { a = t * 0.39; printf "%.6f,%.6f,0,%.6f,%.6f,0.3,0,0.2,1\n", cos(a), sin(a), cos(a), sin(a) }' \
      >>"$in/probe.csv"
  done
  local backend
  for backend in cpu gpu; do
    "$patina" probe --in "$in/probe.csv" --out "$out/probe-$backend.csv" --backend "$backend" >/dev/null
    "$patina" probe --scene "$in/torus.json" --material "$here/presets/gold.json" --in "$in/probe.csv" \
      --out "$out/probe-gold-$backend.csv" --backend "$backend" >/dev/null
  done
  "$patina" lobe --material "$here/presets/brass.json" --theta-in 35 --samples 19 --out "$out/lobe.csv" >/dev/null
  "$patina" export --material "$here/presets/gold.json" --mesh sphere --out "$out/export.gltf" >/dev/null
  "$patina" export --material "$here/presets/gold.json" --mesh "$in/model.glb" --out "$out/export.glb" >/dev/null
  echo "compare_outputs: $(find "$out" -maxdepth 1 -type f | wc -l) files in $out"
}

diff_dirs() {
  local a=$1 b=$2 differ=0 same=0 f
  for f in "$a"/*; do
    [ -f "$f" ] || continue
    if cmp -s "$f" "$b/$(basename "$f")"; then
      same=$((same + 1))
    else
      echo "differs: $(basename "$f")"
      differ=$((differ + 1))
    fi
  done
  echo "compare_outputs: $same identical, $differ differ"
  [ "$differ" = 0 ]
}

case "${1:-}" in
  run) run "$2" "$3" ;;
  diff) diff_dirs "$2" "$3" ;;
  *) sed -n '2,12p' "$0"; exit 2 ;;
esac
