# Sourced by scripts/measure_editor.sh and scripts/compare_blender.sh: drags the editor's
# Roughness slider back and forth for about 3 s with xdotool, as an artist would.
# Usage: drag_roughness WINDOW LAYOUT_JSON (the PATINA_UI_LAYOUT dump of the running editor).
drag_roughness() {
  local window=$1 layout=$2 x0 y0 x1 y1 y left right step
  read -r x0 y0 x1 y1 < <(grep -o '"Roughness": \[[^]]*\]' "$layout" | head -1 | sed 's/.*\[//; s/\]//; s/,//g')
  y=$(( (${y0%.*} + ${y1%.*}) / 2 )) left=${x0%.*} right=${x1%.*}
  xdotool mousemove --window "$window" $(( left + 5 )) "$y" mousedown 1
  for step in $(seq 0 30); do
    xdotool mousemove --window "$window" $(( left + 5 + (right - left - 10) * (step % 10) / 10 )) "$y"
    sleep 0.1
  done
  xdotool mouseup 1
}
