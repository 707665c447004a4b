#!/usr/bin/env bash
# Measures the editor as an artist uses it (docs/PERFORMANCE.md): starts it under its own Xvfb
# with --stats, drags the Roughness slider for about 3 s with xdotool, and prints the --stats
# log: time to first frame, the drag's frame times, peak memory; then the idle resident memory.
# Usage: bash scripts/measure_editor.sh [BUILD_DIR]   (needs xvfb and xdotool: scripts/setup.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
patina="$(pwd)/${1:-build}/app/patina"
work=$(mktemp -d)
trap 'kill "${editor:-}" "${xvfb:-}" 2>/dev/null || true; rm -rf "$work"' EXIT
Xvfb -displayfd 4 -screen 0 1280x800x24 -nolisten tcp 4>"$work/display" &
xvfb=$!
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
export DISPLAY=":$(head -1 "$work/display")"
mkdir -p "$work/config"
XDG_CONFIG_HOME="$work/config" PATINA_UI_LAYOUT="$work/layout.json" "$patina" --stats 2>"$work/stats.log" &
editor=$!
for _ in $(seq 600); do grep -q '"Roughness"' "$work/layout.json" 2>/dev/null && break; sleep 0.1; done
window=$(xdotool search --sync --name Patina | head -1)
source scripts/drag_slider.sh
drag_roughness "$window" "$work/layout.json"
sleep 3   # idle: let the full-quality frame and the thumbnails settle
echo "idle resident memory: $(awk '/VmRSS/ {print int($2 / 1024) " MB"}' "/proc/$editor/status")"
sleep 0.5
cat "$work/stats.log"
