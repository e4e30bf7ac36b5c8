#!/usr/bin/env bash
# Starts the IDE under Xvfb on a project (default: the Vigor traffic light) and saves a
# picture of the window: bash scripts/screenshot.sh [FILE] [OUT.png] [tabs|side] [en|hu|it]
# [new|save|open|about|examples] (side: ladder and instruction list side by side, the README's
# picture; the language of the interface; a dialog or File > Examples pictured over the window:
# the whole screen is saved).
# RUNG_SCREEN=1366x768 sets the screen's size (default 1600x1000). With openbox installed the
# windows get their title bars (apt-get install openbox; not needed by the tests).
set -euo pipefail
cd "$(dirname "$0")/.."
file="${1:-resources/examples/vigor/traffic-light.rung}"
out="${2:-docs/screenshot.png}"
build="${RUNG_BUILD_DIR:-build}"
if [ ! -x "$build/app/rungstudio" ]; then
    cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRUNG_BUILD_TESTS=OFF >/dev/null
    cmake --build "$build" --target rungstudio
fi
# A throw-away settings directory: the picture shows the defaults a new user sees.
export XDG_CONFIG_HOME="$(mktemp -d)" XDG_DATA_HOME="$(mktemp -d)"
mkdir -p "$XDG_CONFIG_HOME/RungStudio"
conf="$XDG_CONFIG_HOME/RungStudio/Rung Studio.conf"
if [ "${3:-tabs}" = side ]; then
    printf '[view]\nsideBySide=true\n' >>"$conf"
fi
if [ -n "${4:-}" ]; then
    printf '[ui]\nlanguage=%s\n' "$4" >>"$conf"
fi
export RUNG_SCREENSHOT_DIALOG="${5:-}"
run="$build/app/rungstudio \"\$@\""
if command -v openbox >/dev/null; then
    # A window manager draws the title bars, so a dialog's title shows as users see it (for
    # looking only; the tests need none).
    run="openbox & sleep 1; $run"
fi
xvfb-run -a -s "-screen 0 ${RUNG_SCREEN:-1600x1000}x24" bash -c "$run" rungstudio "$file" \
    --screenshot "$out"
echo "Saved $out"
