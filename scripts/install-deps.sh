#!/usr/bin/env bash
# Installs the Debian 12 packages Rung Studio needs to build, test and run (as root).
# Only what is missing is installed; a machine that has everything is left alone.
set -euo pipefail
packages=(
    build-essential cmake ninja-build pkg-config clang
    qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-svg-dev libgl-dev
    libqscintilla2-qt6-dev libserialport-dev
    qt6-translations-l10n
    libgtest-dev libbenchmark-dev
    xvfb xauth poppler-utils
    mbpoll libmodbus-dev python3-pymodbus python3-serial-asyncio socat
    # The installed files and the .deb (packaging/, scripts/check-package.sh): icons rendered,
    # docs as HTML, the package's dependencies found, and the checks of what it installs.
    librsvg2-bin cmark-gfm dpkg-dev file desktop-file-utils appstream libxml2-utils lintian
    shared-mime-info xdg-utils libfile-mimeinfo-perl hicolor-icon-theme bash-completion man-db
    # Compare as a git diff driver (docs/version-control.md) and the PLCopen schema check.
    git
)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
    echo "Installing: ${missing[*]}"
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
