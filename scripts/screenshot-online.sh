#!/usr/bin/env bash
# The IDE online to the virtual PLC, pictured under Xvfb (docs/screenshots/online-LANG.png):
# `rungstudio-cli serve FILE --protocol vigor --pty` serves the program on a pseudo-terminal,
# the IDE opens the same program with that port remembered in its settings, and Ctrl+W (sent
# with xdotool) goes online: the ladder shows the running PLC's values.
# bash scripts/screenshot-online.sh [en|hu|it]
set -euo pipefail
cd "$(dirname "$0")/.."
lang="${1:-en}"
build="${RUNG_BUILD_DIR:-build}"
file="${RUNG_ONLINE_FILE:-resources/examples/vigor/traffic-light.rung}"
out="docs/screenshots/online-$lang.png"
export XDG_CONFIG_HOME="$(mktemp -d)" XDG_DATA_HOME="$(mktemp -d)"
mkdir -p "$XDG_CONFIG_HOME/RungStudio"
conf="$XDG_CONFIG_HOME/RungStudio/Rung Studio.conf"
log="$(mktemp)"
"$build/app/rungstudio-cli" serve "$file" --protocol vigor --pty >"$log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 50); do
    grep -q '^/dev/' "$log" && break
    sleep 0.1
done
pty="$(head -n1 "$log")"
printf '[online]\nport=%s\n[ui]\nlanguage=%s\n' "$pty" "$lang" >>"$conf"
xvfb-run -a -s "-screen 0 1366x768x24" bash -c '
    command -v openbox >/dev/null && { openbox & sleep 1; }
    "$1" "$2" &
    app=$!
    sleep 6
    win=$(xdotool search --sync --name "Rung Studio" | tail -n1)
    xdotool windowactivate --sync "$win" || true
    xdotool key --window "$win" --clearmodifiers ctrl+w
    sleep 4
    import -window root "$3"
    kill $app' shot "$build/app/rungstudio" "$file" "$out"
echo "Saved $out"
