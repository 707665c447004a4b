#!/usr/bin/env bash
# Patina side by side with Blender 3.4 Eevee, what an artist would use instead (issue 18,
# docs/PERFORMANCE.md "Blender 3.4 Eevee side by side"). In one run it renders the same UV sphere,
# material (presets/gold.json) and HDRI (Blender's own studio.exr) at 512x512 with both, and
# prints a table of:
#   - Eevee: the first render and the median re-render after a roughness change, both timed
#     inside one Blender process (scripts/blender_render.py), and the whole `blender` process
#     from its start to the first image written;
#   - Patina: a cold `patina render` (empty environment cache: the HDRI is decoded and
#     prefiltered in that run), the median of 5 warm ones, both as whole-process wall times, and
#     the editor's median frame time while the Roughness slider is dragged (`patina SCENE
#     --stats`, driven by xdotool as scripts/measure_editor.sh does, with window and panel sizes
#     that make its viewport 512x512 too);
#   - the two ratios issue 18 sets goals for: Eevee re-render / Patina drag frame (50x) and
#     Eevee first render / Patina cold render (5x).
# It writes both images side by side, captioned, to docs/performance/blender_eevee_vs_patina.png.
#
# With --model FILE (issue 25) a glTF model with its own textured materials takes the sphere's
# place in both, under the same HDRI and camera: Blender imports it with its own glTF importer,
# Patina's scene names it as its mesh, the re-renders and the editor's drag change its first
# material's roughness, and the picture is blender_eevee_vs_patina_STEM.png.
#
# With --shadows (issue 37 item 6) both sides also have one shadow-casting sun and a floor: in
# Blender a Sun lamp with Eevee's soft shadows (its angle, 3 degrees, makes the penumbra) and a
# plane of Patina's floor's size, place and material; in Patina's scene a directional light
# along the same direction with "shadows": true, of the same strength (the irradiance on a
# surface facing it), and display.ground "floor". A --model is then framed from its bounding
# box (blender_render.py --bounds) as compare_cycles.sh frames it; the sphere keeps the default
# view. The goal is 100x the drag frame, and the picture's name ends in _shadows.
#
# Usage: bash scripts/compare_blender.sh [--model F.gltf|F.glb] [--shadows]   (BUILD_DIR overrides build/)
#
# Installs Debian's `blender` (3.4.1) and python3-numpy (blender_render.py cleans the HDRI with
# it, and Blender's glTF importer needs it) with apt when they are missing (as root, else with
# sudo; scripts/blender_setup.sh, shared with compare_cycles.sh) and builds Patina
# (scripts/build.sh) when build/app/patina is missing. Eevee needs an OpenGL context even with
# `blender -b`, and the editor a window, so both run on an Xvfb of the script's own
# (xvfb and xdotool come with scripts/setup.sh); nothing is shown on your display. Everything
# shares one fresh Mesa shader cache (MESA_SHADER_CACHE_DIR), so the first Blender render and
# the cold Patina render compile their shaders from nothing. Temporary files, the Xvfb and the
# editor are removed on exit, also on failure or Ctrl+C.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build_dir=${BUILD_DIR:-build}
patina="$root/$build_dir/app/patina"
hdri=/usr/share/blender/datafiles/studiolights/world/studio.exr
preset="$root/presets/gold.json"
picture="$root/docs/performance/blender_eevee_vs_patina.png"
model='' shadows=''
while [ $# -gt 0 ]; do
  case $1 in
    --model)
      [ -f "${2:-}" ] || { echo "compare_blender: --model needs a .gltf or .glb file" >&2; exit 2; }
      model=$(realpath "$2")
      stem=$(basename "$model"); stem=${stem%.*}
      picture="$root/docs/performance/blender_eevee_vs_patina_$stem.png"
      shift 2 ;;
    --shadows) shadows=1; shift ;;
    *) echo "compare_blender: unknown argument '$1' (usage: [--model F.gltf|F.glb] [--shadows])" >&2; exit 2 ;;
  esac
done
[ -z "$shadows" ] || picture="${picture%.png}_shadows.png"
size=512
warm_runs=5
# Blender's Environment Texture puts the image's centre along its +X; Patina's lies along its -Z,
# which is Blender's +Y. Turning Blender's lookup by -90 degrees about +Z matches the two, and
# blender_render.py --probe checks that by rendering before anything is timed. Patina's
# environment keeps rotationDegrees 0.
blender_world_rotation=-90
patina_rotation=0
# --shadows: the sun, where its light travels in Patina's axes (from the upper left of the
# framed model, so that its shadows fall where the camera sees them), its strength and Eevee's
# angle; the model's camera orbit (theta, phi in degrees, zoom) as compare_cycles.sh's, and the
# field of view of the default camera.
sun_direction='0.5 -1 -0.3' sun_strength=3 sun_angle=3
orbit='30 65 0.8' fov=45

say() { echo "compare_blender: $*" >&2; }
die() { say "error: $*"; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/patina-blender.XXXXXX")
xvfb_pid='' editor_pid=''
cleanup() {
  local pid
  for pid in $editor_pid $xvfb_pid; do
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# Seconds between two $EPOCHREALTIME stamps.
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { printf "%.3f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

load_at_start=$(cut -d' ' -f1-3 /proc/loadavg)   # other work on the machine slows both sides

# --- 1. Blender ----------------------------------------------------------------------------
# shellcheck source=scripts/blender_setup.sh
source "$root/scripts/blender_setup.sh"
ensure_blender numpy
[ -f "$hdri" ] || die "$hdri is missing (Debian's blender-data package ships it)"

# --- 2. Patina -----------------------------------------------------------------------------
if [ ! -x "$patina" ]; then
  say "$patina is missing: building (scripts/build.sh, 10-20 minutes the first time)"
  BUILD_DIR="$build_dir" bash scripts/build.sh || die "the build failed"
fi
for tool in Xvfb xdotool python3; do
  command -v "$tool" >/dev/null || die "$tool is missing: run scripts/setup.sh"
done

# --- A display of our own --------------------------------------------------------------------
Xvfb -displayfd 4 -screen 0 1280x1024x24 -nolisten tcp 4>"$work/display" 2>"$work/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
if [ ! -s "$work/display" ]; then
  cat "$work/xvfb.log" >&2
  die "Xvfb gave no display within 10 s"
fi
DISPLAY=":$(head -1 "$work/display")"
export DISPLAY
export MESA_SHADER_CACHE_DIR="$work/mesa-cache"
mkdir -p "$MESA_SHADER_CACHE_DIR"

# --- 3. Eevee --------------------------------------------------------------------------------
say "checking the environment's orientation in Blender (a probe render)"
run_blender "$work/probe.log" --hdri "$hdri" --probe --world-rotation "$blender_world_rotation"
grep '^probe:' "$work/probe.log" >&2 || true

staging=() patina_staging=''
if [ -n "$shadows" ]; then
  camera="0 0.6 3.4 0 0 0"
  if [ -n "$model" ]; then
    run_blender "$work/bounds.log" --hdri "$hdri" --model "$model" --bounds
    bounds=$(value "$work/bounds.log" bounds)
    [ -n "$bounds" ] || die "Blender reported no bounding box for $model"
    # shellcheck disable=SC2086   # the orbit's three numbers
    camera=$(orbit_camera "$bounds" $orbit "$fov")
  fi
  # shellcheck disable=SC2206   # numbers
  staging=(--camera $camera "$fov" --sun $sun_direction "$sun_strength" "$sun_angle" --ground)
  patina_staging=$(python3 - "$camera" "$fov" "$sun_direction" "$sun_strength" <<'PY'
import json, sys
camera = [float(v) for v in sys.argv[1].split()]
print(json.dumps({
    "camera": {"position": camera[0:3], "target": camera[3:6], "fovYDegrees": float(sys.argv[2])},
    "light": {"type": "directional", "name": "sun", "enabled": True, "color": [1.0, 1.0, 1.0],
              "intensity": float(sys.argv[4]), "direction": [float(v) for v in sys.argv[3].split()],
              "shadows": True},
    "ground": "floor"}))
PY
)
fi

say "rendering with Blender $blender_version Eevee: the first image, then $warm_runs re-renders after a roughness change"
blender_start=$EPOCHREALTIME
if [ -n "$model" ]; then shown=(--model "$model"); else shown=(--material "$preset"); fi
run_blender "$work/blender.log" --hdri "$hdri" "${shown[@]}" --out "$work/eevee.png" \
  --scratch "$work/eevee_rerender.png" --size "$size" --reruns "$warm_runs" --world-rotation "$blender_world_rotation" \
  "${staging[@]}"
[ -s "$work/eevee.png" ] || die "Blender wrote no image"
eevee_first=$(value "$work/blender.log" first_render_s)
eevee_rerender=$(value "$work/blender.log" rerender_median_s)
eevee_rerenders=$(value "$work/blender.log" rerender_s)
eevee_settings=$(value "$work/blender.log" eevee_settings)
gl_renderer=$(value "$work/blender.log" gl_renderer)
blender_to_image=$(elapsed "$blender_start" "$(value "$work/blender.log" first_image_written_epoch)")

# --- 4. Patina -------------------------------------------------------------------------------
scene="$work/scene.json"
python3 - "$preset" "$hdri" "$patina_rotation" "$model" "$patina_staging" >"$scene" <<'PY'
import json, sys
preset = json.load(open(sys.argv[1], encoding="utf-8"))
material = {key: preset[key] for key in ("format", "version", "name", "baseColor", "roughness", "specular", "metallic")}
scene = {
    "format": "patina-scene", "version": 2, "mesh": sys.argv[4] or "sphere", "material": material,
    "camera": {"position": [0.0, 0.6, 3.4], "target": [0.0, 0.0, 0.0], "fovYDegrees": 45.0},
    "lights": [{"type": "environment", "name": "studio", "enabled": True, "source": sys.argv[2],
                "intensity": 1.0, "rotationDegrees": float(sys.argv[3])}],
    "display": {"exposure": 0.0, "tonemap": "none", "background": [0.0, 0.0, 0.0],
                "backgroundEnvironment": True, "backgroundBlur": 0.0},
}
if sys.argv[5]:   # --shadows: the framed camera, the sun and the floor
    staging = json.loads(sys.argv[5])
    scene["camera"] = staging["camera"]
    scene["lights"].append(staging["light"])
    scene["display"]["ground"] = staging["ground"]
print(json.dumps(scene, indent=2))
PY

export PATINA_CACHE_DIR="$work/patina-cache"   # empty: the first render decodes and prefilters
mkdir -p "$PATINA_CACHE_DIR"
patina_render() {   # OUT.png: one whole `patina render`, its wall time in seconds on stdout
  local start=$EPOCHREALTIME
  if ! "$patina" render --scene "$scene" --width "$size" --height "$size" --out "$1" 2>"$work/render.log"; then
    cat "$work/render.log" >&2
    die "patina render failed"
  fi
  elapsed "$start" "$EPOCHREALTIME"
}
say "rendering with Patina: cold (empty environment cache), then $warm_runs warm"
patina_cold=$(patina_render "$work/patina.png")
[ -n "$(ls -A "$PATINA_CACHE_DIR")" ] || say "warning: the cold render left nothing in PATINA_CACHE_DIR: were the warm renders warm?"
warm_times=()
for _ in $(seq "$warm_runs"); do
  warm_times+=("$(patina_render "$work/patina_warm.png")")
done
patina_warm=$(median "${warm_times[@]}")
# Where the cold render's time goes: the same with the environment cache empty again but Mesa's
# shader cache warm. Cold minus this is compiling shaders; this minus warm, preparing the HDRI.
export PATINA_CACHE_DIR="$work/patina-cache-2"
mkdir -p "$PATINA_CACHE_DIR"
patina_cold_env=$(patina_render "$work/patina_cold_env.png")
export PATINA_CACHE_DIR="$work/patina-cache"   # the editor reads the warm one

say "dragging the Roughness slider in the editor (patina SCENE --stats)"
# A window and panel sizes (the editor's remembered settings) that leave the viewport 512x512,
# the size of the renders; the table says the size it had.
mkdir -p "$work/config/patina"
echo '{"windowWidth": 1280, "windowHeight": 900, "leftPanelWidth": 404, "rightPanelWidth": 340, "lobePanelHeight": 263}' \
  >"$work/config/patina/settings.json"
XDG_CONFIG_HOME="$work/config" PATINA_UI_LAYOUT="$work/layout.json" "$patina" "$scene" --stats 2>"$work/stats.log" &
editor_pid=$!
for _ in $(seq 600); do
  grep -q '"Roughness"' "$work/layout.json" 2>/dev/null && break
  kill -0 "$editor_pid" 2>/dev/null || { cat "$work/stats.log" >&2; die "the editor exited before showing its window"; }
  sleep 0.1
done
grep -q '"Roughness"' "$work/layout.json" 2>/dev/null || die "the editor showed no Roughness slider within 60 s"
sleep 2   # the scene's environment comes from the warm cache; let its first frames settle
window=$(timeout 30 xdotool search --sync --name Patina | head -1) || true
[ -n "$window" ] || die "xdotool found no window named Patina"
rect() { grep -o "\"$1\": \[[^]]*\]" "$work/layout.json" | head -1 | sed 's/.*\[//; s/\]//; s/,//g'; }
source "$root/scripts/drag_slider.sh"
drag_roughness "$window" "$work/layout.json"
sleep 2   # the drag's line is logged at the first frame after it
read -r vx0 vy0 vx1 vy1 < <(rect viewport)
viewport="$(awk -v a="$vx0" -v b="$vx1" 'BEGIN { printf "%d", b - a + 0.5 }')x$(awk -v a="$vy0" -v b="$vy1" 'BEGIN { printf "%d", b - a + 0.5 }')"
kill "$editor_pid" 2>/dev/null || true
wait "$editor_pid" 2>/dev/null || true
editor_pid=''
[ "$viewport" = "${size}x${size}" ] || say "warning: the editor's viewport was $viewport, not ${size}x${size}"
drag_line=$(grep 'stats: drag:' "$work/stats.log" | tail -1)
[ -n "$drag_line" ] || { cat "$work/stats.log" >&2; die "the editor logged no drag (did the slider move?)"; }
drag_ms=$(sed -E 's/.*median ([0-9.]+) ms.*/\1/' <<<"$drag_line")
drag_frames=$(sed -E 's/.*drag: ([0-9]+) frames.*/\1/' <<<"$drag_line")
drag_p90=$(sed -E 's/.*p90 ([0-9.]+) ms.*/\1/' <<<"$drag_line")

# --- 5. The picture and the table --------------------------------------------------------------
mkdir -p "$(dirname "$picture")"
eevee_caption="Blender $blender_version Eevee, Standard view" patina_caption="Patina, tone map none"
[ -z "$shadows" ] || eevee_caption="Eevee, soft shadows" patina_caption="Patina, shadows"
python3 "$root/scripts/side_by_side.py" "$picture" \
  "$work/eevee.png" "$eevee_caption" \
  "$work/patina.png" "$patina_caption" || die "could not write $picture"

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", a / b }'; }
verdict() { awk -v r="$1" -v goal="$2" 'BEGIN { print (r >= goal ? "met" : "missed") }'; }
drag_ratio=$(ratio "$(awk -v s="$eevee_rerender" 'BEGIN { print s * 1000 }')" "$drag_ms")
cold_ratio=$(ratio "$eevee_first" "$patina_cold")
ms() { awk -v s="$1" 'BEGIN { printf "%.0f ms", s * 1000 }'; }
drag_goal=50 staged='' shadow_settings=''
if [ -n "$shadows" ]; then
  drag_goal=100
  staged=", a sun along ($sun_direction) of strength $sun_strength casting shadows (Eevee: soft, ${sun_angle} degrees across; Patina: its shadow map) and the floor under it; camera $camera, ${fov} degrees"
  shadow_settings="; $(value "$work/blender.log" eevee_shadow_settings); $(value "$work/blender.log" ground)"
fi

cat <<EOF

Blender $blender_version Eevee against Patina ($(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo "no git")), ${size}x${size}, $(nproc) cores, OpenGL: $gl_renderer
Shown: ${model:-the UV sphere with presets/gold.json} under ${hdri##*/}$staged
Load average at the start (1, 5, 15 min): $load_at_start; at the end: $(cut -d' ' -f1-3 /proc/loadavg)
Eevee: $eevee_settings$shadow_settings
Eevee re-renders (s): $eevee_rerenders; Patina warm renders (s): ${warm_times[*]}
Editor viewport: $viewport pixels (the drag: $drag_frames frames, p90 $drag_p90 ms)

| measurement | time |
|---|---:|
| Eevee, first render (inside Blender) | $(ms "$eevee_first") |
| Eevee, re-render after a roughness change (median of $warm_runs) | $(ms "$eevee_rerender") |
| Blender process, start to first image written | $(ms "$blender_to_image") |
| Patina render, cold (empty environment cache) | $(ms "$patina_cold") |
| Patina render, warm (median of $warm_runs) | $(ms "$patina_warm") |
| (Patina render, empty environment cache, shaders in Mesa's cache) | $(ms "$patina_cold_env") |
| Patina editor, frame while dragging Roughness (median; viewport $viewport) | $drag_ms ms |

| ratio | measured | goal | |
|---|---:|---:|---|
| Eevee re-render / Patina drag frame | ${drag_ratio}x | ${drag_goal}x | $(verdict "$drag_ratio" "$drag_goal") |
| Eevee first render / Patina cold render | ${cold_ratio}x | 5x | $(verdict "$cold_ratio" 5) |

Picture: ${picture#"$root"/}
EOF
