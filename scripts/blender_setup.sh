# shellcheck shell=bash
# Sourced by scripts/compare_blender.sh and scripts/compare_cycles.sh: Debian's Blender (3.4.1),
# installed with apt when it is missing (as root, else with sudo), and python3-numpy, which its
# glTF importer needs and the package only recommends; and orbit_camera, the two scripts' camera
# about a model's box. Needs the caller's `say` and `die`, and
# $root, the repository.
# shellcheck disable=SC2154   # root: the caller's

# ensure_blender [numpy]: blender (and with "numpy" python3-numpy) present, or die; then
# $blender_version holds its version, with a warning when it is not the 3.4 the scripts were
# written for.
ensure_blender() {
  local packages=()
  if ! command -v blender >/dev/null; then
    packages+=(blender)
    [ "${1:-}" != numpy ] || packages+=(python3-numpy)
  elif [ "${1:-}" = numpy ] &&
    ! blender -b --factory-startup --python-exit-code 1 --python-expr 'import numpy' >/dev/null 2>&1; then
    packages+=(python3-numpy)   # asked of Blender's Python, which need not be the python3 on PATH
  fi
  if [ ${#packages[@]} -gt 0 ]; then
    say "installing Debian's ${packages[*]} (Blender, and numpy for its glTF importer)"
    local sudo_cmd=()
    if [ "$(id -u)" -ne 0 ]; then
      command -v sudo >/dev/null ||
        die "this is not root and there is no sudo: install them with 'apt-get install --no-install-recommends ${packages[*]}'"
      sudo_cmd=(sudo)
    fi
    export DEBIAN_FRONTEND=noninteractive
    "${sudo_cmd[@]}" apt-get update -qq || die "apt-get update failed"
    "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${packages[@]}" ||
      die "installing ${packages[*]} failed"
  fi
  blender_version=$(blender --factory-startup --version 2>/dev/null | awk '/^Blender [0-9]/ { print $2; exit }')
  [ -n "$blender_version" ] || die "'blender --version' printed no version: is $(command -v blender) Blender?"
  case $blender_version in
    3.4.*) ;;
    *) say "warning: Blender $blender_version, not the 3.4 this comparison was written for (Debian 12's)" ;;
  esac
}

# run_blender LOG ARGS...: scripts/blender_render.py with ARGS, its output to LOG; on failure the
# log's end and an error.
run_blender() {
  local log=$1
  shift
  if ! blender -b --factory-startup --python "$root/scripts/blender_render.py" -- "$@" >"$log" 2>&1; then
    tail -25 "$log" >&2
    die "blender failed (its log's end is above)"
  fi
}

# value LOG KEY: what blender_render.py reported as "PATINA_COMPARE KEY VALUE".
value() { awk -v key="$2" '$1 == "PATINA_COMPARE" && $2 == key { $1 = ""; $2 = ""; sub(/^ +/, ""); print; exit }' "$1"; }

# orbit_camera BOUNDS THETA PHI ZOOM FOV: "EX EY EZ TX TY TZ" for the box "X0 Y0 Z0 X1 Y1 Z1"
# (Patina's axes, blender_render.py --bounds), eye = target + d (sin phi sin theta, cos phi,
# sin phi cos theta) as model-viewer's camera-orbit about the box's centre (THETA, PHI in
# degrees), d = ZOOM * radius / sin(FOV / 2): ZOOM 1 fits the bounding sphere in the view.
orbit_camera() {
  awk -v b="$1" -v theta="$2" -v phi="$3" -v zoom="$4" -v fov="$5" 'BEGIN {
    split(b, v, " "); pi = atan2(0, -1)
    cx = (v[1] + v[4]) / 2; cy = (v[2] + v[5]) / 2; cz = (v[3] + v[6]) / 2
    r = sqrt((v[4] - v[1])^2 + (v[5] - v[2])^2 + (v[6] - v[3])^2) / 2
    d = zoom * r / sin(fov * pi / 360); t = theta * pi / 180; p = phi * pi / 180
    printf "%.6g %.6g %.6g %.6g %.6g %.6g", cx + d * sin(p) * sin(t), cy + d * cos(p), cz + d * sin(p) * cos(t), cx, cy, cz
  }'
}
