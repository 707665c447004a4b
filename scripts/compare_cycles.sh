#!/usr/bin/env bash
# Patina side by side with Blender 3.4's Cycles and with its own ground truth, as a user would
# check a glTF asset (issue 35, item 6; docs/LIGHTING.md, "5. Side by side with Cycles"). The
# truth is glTF 2.0's BRDF (Appendix B, single scattering) integrated by Patina's reference
# (`render --reference --model gltf`); Cycles, whose Principled BSDF v1 is not glTF's model
# either, is a second opinion.
#
# Four scenes, each under one HDRI (Blender's studio.exr, as compare_blender.sh's; HDRI=F
# another) from one camera: BoxTextured and 2CylinderEngine (assimp's glTF 2.0 samples) and a
# grid of spheres, roughness 0 to 1 across and metallic 0, 0.5, 1 down, of one base colour
# (scripts/sphere_grid.py), and Khronos's ClearCoatTest (KHR_materials_clearcoat: a base column,
# the same coated, and the coat alone; Blender's importer reads the coat into the Principled
# BSDF's Clearcoat, Clearcoat Roughness and Clearcoat Normal), and the layer grid Blender 3.4
# itself exported (tests/data/layers/make_layers.py: a plain sphere, a coat, a sheen and a
# specular on one red base, then a clear, a rough, an IOR 2.4 and an absorbing volume's
# transmission; Blender's importer reads them back into its Principled BSDF, a Velvet BSDF and a
# Volume Absorption, so Cycles renders Blender's own layers, not glTF's). The cameras orbit each model's
# bounding box as model-viewer's camera-orbit does (its centre the target; Blender reports the
# box, blender_render.py --bounds) and both renderers are given the same eye, target and field of
# view. Each scene is rendered at twice the compared size by
#   - Patina with `--model epic` (the seed's UE4 model), `gltf` (glTF's, the default of a glTF
#     file's materials) and `gltf-single` (glTF's without the split sum's multiple scattering);
#   - Patina's ground truth of `gltf` at REFERENCE_SAMPLES, and at a quarter of them (its noise);
#   - Cycles at CYCLES_SAMPLES as a user renders (shadows and interreflection, Blender's
#     defaults but for the pixel filter), at a quarter of them with another seed (its noise), and
#     with the model hidden from every ray but the camera's ("cycles-local": each point lit by
#     the whole sky, as Patina and its ground truth light it, so that only the materials differ);
#   - Patina's own occlusion of the environment by the model: `gltf` with the scene's
#     display.ambientOcclusion (`gltf-ao`, the per-vertex bake) and the ground truth with
#     `--visibility` at REFERENCE_SAMPLES (`truth-visibility`), whose natural match is Cycles
#     as rendered (neither has Cycles' interreflection);
#   - both renderers' base colours alone (`--channel base-color --reference`; Cycles with each
#     material's base colour as emission), which must agree where the view, the UVs and the
#     texture filtering do: the check that the two see the same thing;
# all linear (Patina's PFMs, Cycles' OpenEXRs), every pixel sampled at its centre (Cycles' pixel
# filter 0.01 pixels wide). `patina difference` then shrinks each by 2 (a box over the pixels:
# the one pixel filter of all), puts every one through one exposure (0) and one tone curve
# (Khronos PBR Neutral, shaders/shared/display.glsl) and sRGB, and takes the mean |difference|
# over R, G, B, in levels of 255, over the pixels that show the model (Patina's coverage, its
# silhouette eroded by one pixel, which each renderer antialiases its own way). Into OUT_DIR:
#   - cycles.csv: scene, image, against, mean |difference|, mean difference (positive: the image
#     is brighter), pixels compared;
#   - cycles.png/.svg/.pdf (`patina chart cycles OUT_DIR`): each model's distance to the truth
#     against its distance to Cycles;
#   - cycles_SCENE.png: the images as displayed and, under each, where it differs from the truth;
# and prints the tables docs/LIGHTING.md quotes (ClearCoatTest's also rendered by Patina `gltf`,
# Cycles and Cycles local without its coat, and measured column by column by
# scripts/clearcoat_columns.py: docs/SHADING.md, S5, quotes it), with each renderer's noise (two
# estimates of one image at N and N/4 samples differ by about sqrt(5) times the mean |noise| at
# N), and the sphere grid and the layer grid sphere by sphere (scripts/sphere_grid_cells.py; the
# layer grid's with the truth at a quarter of its samples, whose distance is sqrt(5) times its noise).
#
# Usage: bash scripts/compare_cycles.sh [--quick] [--out-dir D] [--work-dir W]
#   --out-dir: default docs/lighting/cycles (with --quick a temporary folder);
#   --quick: a quarter of the samples, to check the pipeline (its numbers are noise-bound);
#   --work-dir: keep the renders there (default: a temporary folder, removed on exit).
# SCENES (names, space separated) renders only those scenes (OUT_DIR's cycles.csv then holds only
# their rows: give another --out-dir and add them to the docs' by hand). BUILD_DIR overrides build/; REFERENCE_SAMPLES
# (default 256) and CYCLES_SAMPLES (default 32) the sample counts, small so that the whole run
# fits in minutes: more lower the noise floors the script prints (1-6 levels at the defaults).
# Installs Debian's `blender` and python3-numpy when missing (scripts/blender_setup.sh) and builds
# Patina (scripts/build.sh) when build/app/patina is missing. Cycles and the ground truth run on
# the CPU: on two cores shared with other work the whole run takes about 10 minutes (ClearCoatTest
# alone about 3; --quick: about 5, most of it Blender starting).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build_dir=${BUILD_DIR:-build}
patina="$root/$build_dir/app/patina"
hdri=${HDRI:-/usr/share/blender/datafiles/studiolights/world/studio.exr}
assimp=/usr/share/assimp/models/glTF2
reference_samples=${REFERENCE_SAMPLES:-256}
cycles_samples=${CYCLES_SAMPLES:-32}
tonemap=pbr-neutral
exposure=0
factor=2        # rendered at factor x the compared size, shrunk by a box
erode=1         # pixels of the silhouette left out
fov=30          # every camera's vertical field of view, degrees
# Blender's Environment Texture turned by -90 degrees about +Z matches Patina's equirect
# orientation (compare_blender.sh; blender_render.py --probe checks it).
blender_world_rotation=-90

say() { echo "compare_cycles: $*" >&2; }
die() { say "error: $*"; exit 1; }

out_dir='' quick=0 work=''
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=1 ;;
    --out-dir) [ -n "${2:-}" ] || die "--out-dir needs a folder"; out_dir=$2; shift ;;
    --work-dir) [ -n "${2:-}" ] || die "--work-dir needs a folder"; work=$(realpath -m "$2"); shift ;;
    *) die "unknown argument '$1' (usage: compare_cycles.sh [--quick] [--out-dir D] [--work-dir W])" ;;
  esac
  shift
done
if [ "$quick" = 1 ]; then
  reference_samples=$(( (reference_samples + 3) / 4 ))
  cycles_samples=$(( (cycles_samples + 3) / 4 ))
fi
(( reference_samples >= 4 && cycles_samples >= 4 )) || die "REFERENCE_SAMPLES and CYCLES_SAMPLES must be at least 4 (a quarter is taken)"

if [ -n "$work" ]; then
  mkdir -p "$work"
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/patina-cycles.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
trap 'exit 130' INT TERM
if [ -z "$out_dir" ]; then
  if [ "$quick" = 1 ]; then out_dir="$work/out"; else out_dir="$root/docs/lighting/cycles"; fi
fi
mkdir -p "$out_dir"

# shellcheck source=scripts/blender_setup.sh
source "$root/scripts/blender_setup.sh"
ensure_blender numpy
[ -f "$hdri" ] || die "$hdri is missing (Debian's blender-data package ships it)"
[ -d "$assimp" ] || die "$assimp is missing (Debian's assimp-testmodels package ships it)"
if [ ! -x "$patina" ]; then
  say "$patina is missing: building (scripts/build.sh, 10-20 minutes the first time)"
  BUILD_DIR="$build_dir" bash scripts/build.sh || die "the build failed"
fi
export PATINA_CACHE_DIR="$work/patina-cache"

python3 "$root/scripts/sphere_grid.py" "$work/sphere_grid.gltf"
# name, file, compared width and height, the camera's orbit about the bounding box's centre as
# model-viewer's camera-orbit (theta, phi in degrees) and its distance in units of the one that
# fits the bounding sphere in the view.
scenes=(
  "spheres $work/sphere_grid.gltf 240 144 0 90 0.59"
  "BoxTextured $assimp/BoxTextured-glTF/BoxTextured.gltf 160 160 35 60 1.05"
  "2CylinderEngine $assimp/2CylinderEngine-glTF-Binary/2CylinderEngine.glb 192 192 30 65 0.8"
  "ClearCoatTest $assimp/ClearCoat-glTF/ClearCoatTest.gltf 168 200 0 90 0.8"
  "layers $root/tests/data/layers/layers.glb 232 120 0 90 0.54"
)

sheet=()
csv="$out_dir/cycles.csv"
echo "scene,image,against,mean_abs_srgb,mean_signed_srgb,pixels" >"$csv"
compare() {   # SCENE_DIR SCENE IMAGE... : patina difference's rows, the scene's name first
  local dir=$1 name=$2
  shift 2
  local paths=() names=() image
  for image in "$@"; do
    names+=("$image")
    if [ -f "$dir/$image.pfm" ]; then paths+=("$dir/$image.pfm"); else paths+=("$dir/$image.exr"); fi
  done
  "$patina" difference "${paths[@]}" --names "${names[@]}" --coverage "$dir/coverage.pfm" --downsample "$factor" \
    --erode "$erode" --exposure "$exposure" --tonemap "$tonemap" --scene "$name" "${sheet[@]}" | tail -n +2 >>"$csv"
}

# coat_off DIR FILE: ClearCoatTest again without its coat (gltf, cycles-local, cycles), for
# scripts/clearcoat_columns.py's "the coat adds". Uses the loop's camera and render helpers.
coat_off() {
  local dir=$1 stripped="$1/nocoat/$(basename "$2")"
  python3 "$root/scripts/clearcoat_columns.py" strip "$2" "$dir/nocoat" || die "stripping the coat failed"
  say "ClearCoatTest without its coat: Patina gltf, Cycles (local and as rendered)"
  file=$stripped write_scene "$dir/scene-nocoat.json" ''
  render_scene "$dir/scene-nocoat.json" gltf-nocoat --model gltf
  local blender_args=("${cycles[@]}")
  blender_args[3]=$stripped   # --model's value
  run_blender "$dir/cycles-nocoat.log" "${blender_args[@]}" --samples "$cycles_samples" --out "$dir/cycles-nocoat.exr"
  run_blender "$dir/cycles-local-nocoat.log" "${blender_args[@]}" --samples "$cycles_samples" --local \
    --out "$dir/cycles-local-nocoat.exr"
}

for line in "${scenes[@]}"; do
  read -r name file width height theta phi zoom <<<"$line"
  [ -z "${SCENES:-}" ] || [[ " $SCENES " == *" $name "* ]] || continue
  dir="$work/$name"
  mkdir -p "$dir"
  [ -f "$file" ] || die "$file is missing"
  run_blender "$dir/bounds.log" --hdri "$hdri" --model "$file" --bounds
  bounds=$(value "$dir/bounds.log" bounds)
  [ -n "$bounds" ] || die "Blender reported no bounding box for $file"
  read -r ex ey ez tx ty tz <<<"$(orbit_camera "$bounds" "$theta" "$phi" "$zoom" "$fov")"
  w=$((width * factor)) h=$((height * factor))
  write_scene() {   # FILE DISPLAY_EXTRA: the scene, DISPLAY_EXTRA added to its display
    cat >"$1" <<EOF
{"format": "patina-scene", "version": 3, "mesh": "$file",
 "camera": {"position": [$ex, $ey, $ez], "target": [$tx, $ty, $tz], "fovYDegrees": $fov},
 "lights": [{"type": "environment", "name": "hdri", "source": "$hdri", "intensity": 1.0, "rotationDegrees": 0}],
 "display": {"exposure": $exposure, "tonemap": "$tonemap", "backgroundEnvironment": true$2}}
EOF
  }
  write_scene "$dir/scene.json" ''
  write_scene "$dir/scene-ao.json" ', "ambientOcclusion": true'
  render_scene() {   # SCENE_FILE OUT_STEM ARGS...: one patina render of SCENE_FILE at the rendered size
    local scene=$1 stem=$2
    shift 2
    "$patina" render --scene "$scene" --width "$w" --height "$h" --out "$dir/$stem.png" --hdr "$dir/$stem.pfm" \
      "$@" 2>"$dir/$stem.log" || { cat "$dir/$stem.log" >&2; die "patina render $stem of $name failed"; }
  }
  render() { render_scene "$dir/scene.json" "$@"; }   # OUT_STEM ARGS...: the scene as written
  say "$name: Patina (coverage, base colour, epic, gltf, gltf-single; ground truth at $reference_samples and $((reference_samples / 4)) samples)"
  render coverage --channel geometry-normal --reference
  render base-color --channel base-color --reference
  for model in epic gltf gltf-single; do render "$model" --model "$model"; done
  render reference --model gltf --reference --reference-samples "$reference_samples"
  render reference-quarter --model gltf --reference --reference-samples $((reference_samples / 4))
  say "$name: Patina with its own occlusion (gltf-ao: display.ambientOcclusion; truth-visibility: --visibility at $reference_samples)"
  render_scene "$dir/scene-ao.json" gltf-ao --model gltf
  render truth-visibility --model gltf --reference --visibility --reference-samples "$reference_samples"

  say "$name: Cycles at $cycles_samples samples (as rendered, and local), and at $((cycles_samples / 4)) with another seed"
  cycles=(--hdri "$hdri" --model "$file" --render-cycles --width "$w" --height "$h" --world-rotation "$blender_world_rotation"
          --camera "$ex" "$ey" "$ez" "$tx" "$ty" "$tz" "$fov")
  run_blender "$dir/cycles.log" "${cycles[@]}" --samples "$cycles_samples" --out "$dir/cycles.exr"
  run_blender "$dir/cycles-local.log" "${cycles[@]}" --samples "$cycles_samples" --local --out "$dir/cycles-local.exr"
  run_blender "$dir/cycles-quarter.log" "${cycles[@]}" --samples $((cycles_samples / 4)) --seed 1 --out "$dir/cycles-quarter.exr"
  run_blender "$dir/cycles-base-color.log" "${cycles[@]}" --samples 4 --base-color --out "$dir/cycles-base-color.exr"
  say "$name: $(value "$dir/cycles.log" cycles_settings), $(value "$dir/cycles.log" cycles_render_s) s"

  sheet=(--sheet "$out_dir/cycles_$name.png")
  compare "$dir" "$name" reference gltf epic gltf-single cycles-local cycles
  sheet=()
  compare "$dir" "$name" reference reference-quarter
  compare "$dir" "$name" cycles-local gltf epic gltf-single
  compare "$dir" "$name" cycles gltf epic gltf-single cycles-quarter
  compare "$dir" "$name" base-color cycles-base-color
  for against in reference cycles-local cycles; do compare "$dir" "$name" "$against" gltf-ao truth-visibility; done
  [ "$name" != ClearCoatTest ] || coat_off "$dir" "$file"
done

"$patina" chart cycles "$out_dir"

# The table: each model against the truth and Cycles, and each renderer's noise.
awk -F, -v rs="$reference_samples" -v cs="$cycles_samples" 'NR > 1 {
    v[$1 "," $2 "," $3] = $4; s[$1 "," $2 "," $3] = $5
    if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 }
  }
  function cell(key) { return (key in v) ? sprintf("%.1f (%+.1f)", v[key], s[key]) : "" }
  END {
    printf "\nmean |sRGB difference| (mean signed difference), levels of 255\n\n"
    print "| scene | image | to the reference | to Cycles, local | to Cycles |"
    print "|---|---|---:|---:|---:|"
    for (i = 1; i <= n; ++i) {
      split("epic gltf gltf-single gltf-ao truth-visibility cycles-local cycles", images, " ")
      for (j = 1; j <= 7; ++j) {
        m = images[j]
        printf "| %s | %s | %s | %s | %s |\n", order[i], m, cell(order[i] "," m ",reference"),
               cell(order[i] "," m ",cycles-local"), cell(order[i] "," m ",cycles")
      }
    }
    printf "\nnoise, the mean |noise| of one image (its two estimates differ by sqrt(5) times it), and the base colours:\n\n"
    print "| scene | reference, " rs " samples | Cycles, " cs " samples | base colour, Cycles to Patina |"
    print "|---|---:|---:|---:|"
    for (i = 1; i <= n; ++i) {
      printf "| %s | %.2f | %.2f | %s |\n", order[i], v[order[i] ",reference-quarter,reference"] / sqrt(5),
             v[order[i] ",cycles-quarter,cycles"] / sqrt(5), cell(order[i] ",cycles-base-color,base-color")
    }
  }' "$csv"
echo
if [ -d "$work/ClearCoatTest" ]; then
  python3 "$root/scripts/clearcoat_columns.py" measure "$patina" "$work/ClearCoatTest" --tonemap "$tonemap" \
    --downsample "$factor" --erode "$erode" || die "clearcoat_columns.py failed"
  echo
fi
if [ -d "$work/layers" ]; then
  python3 "$root/scripts/sphere_grid_cells.py" "$patina" "$work/layers" --tonemap "$tonemap" --downsample "$factor" \
    --erode "$erode" --images gltf,cycles-local,cycles,reference-quarter \
    --names "plain,clearcoat,sheen,specular;transmission,rough transmission,ior,volume" || die "sphere_grid_cells.py failed"
  echo
fi
if [ -d "$work/spheres" ]; then
  python3 "$root/scripts/sphere_grid_cells.py" "$patina" "$work/spheres" --tonemap "$tonemap" --downsample "$factor" \
    --erode "$erode" || die "sphere_grid_cells.py failed"
fi
echo
echo "CSV: ${csv#"$root"/}; chart: ${out_dir#"$root"/}/cycles.png; pictures: ${out_dir#"$root"/}/cycles_*.png"
