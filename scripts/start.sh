#!/usr/bin/env bash
# Installs what is missing, builds, and starts the IDE on an example project.
# Without a display (no $DISPLAY) the IDE runs under Xvfb.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRUNG_BUILD_TESTS=OFF >/dev/null
cmake --build build --target rungstudio rungstudio-cli
example="resources/examples/vigor/traffic-light.rung"
[ -f "$example" ] || example=""
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
    exec build/app/rungstudio $example "$@"
else
    echo "No display found: starting the IDE under Xvfb."
    exec xvfb-run -a -s "-screen 0 1600x1000x24" build/app/rungstudio $example "$@"
fi
