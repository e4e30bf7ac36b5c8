#!/usr/bin/env bash
# Pictures stepping inside a scan, as a user gets there with the keys: the traffic light side
# by side, run for a few seconds, a breakpoint on the ladder cursor's rung (rung 1, Ctrl+B),
# stopped there, two instructions stepped (Ctrl+F12), the Scan Debugger showing the logic
# result and the stacks.
#   bash scripts/screenshot-stepping.sh [en|hu|it] [OUT.png]
# Needs Xvfb, xdotool and ImageMagick's import (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
lang="${1:-en}"
out="${2:-docs/screenshots/stepping-$lang.png}"
build="${RUNG_BUILD_DIR:-build}"
screen="${RUNG_SCREEN:-1366x768}"
export XDG_CONFIG_HOME="$(mktemp -d)" XDG_DATA_HOME="$(mktemp -d)"
mkdir -p "$XDG_CONFIG_HOME/RungStudio"
printf '[view]\nsideBySide=true\n[ui]\nlanguage=%s\n' "$lang" >"$XDG_CONFIG_HOME/RungStudio/Rung Studio.conf"
display=":$((90 + RANDOM % 100))"
Xvfb "$display" -screen 0 "${screen}x24" -nolisten tcp &
xvfb=$!
trap 'kill "$app" "$xvfb" 2>/dev/null || true' EXIT
sleep 1
export DISPLAY="$display"
"$build/app/rungstudio" resources/examples/vigor/traffic-light.rung &
app=$!
window=""
for _ in $(seq 1 60); do
    window="$(xdotool search --pid "$app" --onlyvisible --class rungstudio 2>/dev/null | head -1 || true)"
    [ -n "$window" ] && break
    sleep 0.5
done
[ -n "$window" ] || { echo "the window did not show" >&2; exit 1; }
sleep 1.5
xdotool windowfocus --sync "$window" 2>/dev/null || xdotool windowfocus "$window"
key() { xdotool key --window "$window" --delay 120 "$@"; sleep 0.4; }
key F10            # Run: the lights start
sleep 3
key ctrl+b         # a breakpoint on rung 1: the next scan stops before its LD M9002
sleep 1
key ctrl+F12 ctrl+F12 # LD M9002, SET S0 run: stopped before STL S0
sleep 1.5
import -window root "$out"
echo "Saved $out"
