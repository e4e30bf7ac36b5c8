#!/usr/bin/env bash
# Builds the Debian package from a configured and built Release build folder and checks what it
# installs, as a user's system would meet it:
#
#   bash scripts/check-package.sh BUILD_DIR [--dpkg]
#
# BUILD_DIR: configured with -DCMAKE_BUILD_TYPE=Release (or RelWithDebInfo), the GUI on, no
# sanitizer (a package of such a build is not what users get), and built. The script builds the
# `package` target, then checks:
#   - the .deb's control fields (section, maintainer, dependencies found by dpkg-shlibdeps) and
#     lintian with no error (the warnings kept are explained below, at LINTIAN_KEPT);
#   - an install into a temporary prefix (`cmake --install --prefix`), moved to another folder
#     afterwards (relocatable): `rungstudio-cli --version`, a `check` of an installed example,
#     the translations found (`--lang hu`), both programs' `--version`;
#   - desktop-file-validate, appstreamcli validate --no-net, xmllint on the MIME file, and the
#     MIME database built from it naming .rung (by its glob and by its magic), .ladder,
#     .rungnet and .rungtest files;
#   - the man pages against `--help`, and the bash completion.
# --dpkg also installs the .deb with apt-get (as root), checks the menu entry, the icons and the
# file type in place through dpkg's triggers, and removes the package again.
# Needs the packages of scripts/install-deps.sh. Prints one line per check and a last line
# "package checks: N passed, N failed"; exits 1 when a check failed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

build=${1:?usage: bash scripts/check-package.sh BUILD_DIR [--dpkg]}
dpkg_too=false
[ "${2:-}" = --dpkg ] && dpkg_too=true
build=$(cd "$build" && pwd)
cache=$build/CMakeCache.txt
[ -f "$cache" ] || { echo "$build is not a configured build folder (no CMakeCache.txt)" >&2; exit 2; }
setting() { sed -n "s/^$1:[A-Z]*=//p" "$cache"; }
# RUNG_PACKAGE_ANY_BUILD=1 lets a developer try the checks on the Debug folder they work in;
# what is shipped, and what CI checks (scripts/test.sh), is a Release build.
case $(setting CMAKE_BUILD_TYPE) in
    Release | RelWithDebInfo | MinSizeRel) ;;
    *) if [ "${RUNG_PACKAGE_ANY_BUILD:-}" != 1 ]; then
           echo "$build is a $(setting CMAKE_BUILD_TYPE) build: configure one with -DCMAKE_BUILD_TYPE=Release" >&2
           exit 2
       fi ;;
esac
for option in RUNG_SANITIZE RUNG_TSAN RUNG_BUILD_FUZZERS; do
    [ "$(setting $option)" != ON ] || { echo "$build has $option=ON: package a build without it" >&2; exit 2; }
done
[ "$(setting RUNG_BUILD_GUI)" != OFF ] || { echo "$build has RUNG_BUILD_GUI=OFF" >&2; exit 2; }

passed=0
failed=0
ok() { echo "ok: $*"; passed=$((passed + 1)); }
bad() { echo "FAILED: $*"; failed=$((failed + 1)); }
check() { # check DESCRIPTION COMMAND...: the command's output is shown when it fails
    local what=$1 out
    shift
    if out=$("$@" 2>&1); then ok "$what"; else bad "$what"; echo "$out" | sed 's/^/    /'; fi
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# ---- The package -------------------------------------------------------------------------------
rm -f "$build"/rungstudio_*.deb
nice -n 10 cmake --build "$build" --target package -j2 >"$work/package.log" 2>&1 ||
    { cat "$work/package.log"; echo "FAILED: cmake --build $build --target package"; exit 1; }
deb=$(ls "$build"/rungstudio_*.deb)
ok "package built: $(basename "$deb")"
version=$(dpkg-deb -f "$deb" Version)
field_is() { [ "$(dpkg-deb -f "$deb" "$1")" = "$2" ] || { echo "$1: $(dpkg-deb -f "$deb" "$1")"; return 1; }; }
check "section electronics" field_is Section electronics
check "a maintainer" bash -c "dpkg-deb -f '$deb' Maintainer | grep -Eq '^[^<]+ <[^@ ]+@[^> ]+>$'"
# dpkg-shlibdeps found the libraries the programs link: Qt, QScintilla, libserialport.
for library in libqt6widgets6 libqscintilla2-qt6 libserialport0 libc6; do
    check "depends on $library" bash -c "dpkg-deb -f '$deb' Depends | grep -q '$library'"
done
dpkg-deb -c "$deb" >"$work/contents"
for file in ./usr/bin/rungstudio ./usr/bin/rungstudio-cli \
    ./usr/share/applications/io.github.rungstudio.RungStudio.desktop \
    ./usr/share/metainfo/io.github.rungstudio.RungStudio.metainfo.xml \
    ./usr/share/mime/packages/io.github.rungstudio.RungStudio.xml \
    ./usr/share/icons/hicolor/scalable/apps/io.github.rungstudio.RungStudio.svg \
    ./usr/share/icons/hicolor/16x16/apps/io.github.rungstudio.RungStudio.png \
    ./usr/share/icons/hicolor/256x256/apps/io.github.rungstudio.RungStudio.png \
    ./usr/share/icons/hicolor/16x16/mimetypes/application-x-rungstudio-project.png \
    ./usr/share/man/man1/rungstudio.1.gz ./usr/share/man/man1/rungstudio-cli.1.gz \
    ./usr/share/bash-completion/completions/rungstudio-cli \
    ./usr/share/doc/rungstudio/copyright ./usr/share/doc/rungstudio/changelog.gz \
    ./usr/share/doc/rungstudio/user-guide.html \
    ./usr/share/rungstudio/examples/vigor/traffic-light.rung; do
    grep -q " $file\$" "$work/contents" || missing+=" $file"
done
if [ -z "${missing:-}" ]; then
    ok "the package holds the programs, the desktop files, icons, man pages, docs and examples"
else
    bad "the package lacks$missing"
fi

# lintian: no error, and today no warning either. With -I --pedantic it also says (kept, as
# information only): hardening-no-bindnow and hardening-no-fortify-functions (the programs are
# built with the project's CMake flags, not dpkg-buildflags' -D_FORTIFY_SOURCE=2 -Wl,-z,now,
# which a Debian source package would add), binary-has-unneeded-section .comment (CPack's
# strip keeps it), possible-documentation-but-no-doc-base-registration (doc-base is optional).
# Running as root, lintian says it is not recommended: that line is left out below.
lintian_status=0
lintian --tag-display-limit 0 --fail-on error,warning "$deb" >"$work/lintian.out" 2>&1 ||
    lintian_status=$?
grep -v 'running with root privileges' "$work/lintian.out" >"$work/lintian" || true
if [ $lintian_status -eq 0 ]; then
    ok "lintian: no error, no warning"
else
    bad "lintian"
fi
sed 's/^/    /' "$work/lintian"

# ---- An install into a temporary prefix, moved afterwards ------------------------------------
cmake --install "$build" --prefix "$work/first" >/dev/null
mv "$work/first" "$work/prefix" # relocatable: nothing may point at the prefix it was installed to
prefix=$work/prefix
cli=$prefix/bin/rungstudio-cli
check "rungstudio-cli --version" bash -c "[ \"\$('$cli' --version)\" = 'rungstudio-cli $version' ]"
check "rungstudio --version without a display" \
    bash -c "[ \"\$(env -u DISPLAY -u WAYLAND_DISPLAY '$prefix/bin/rungstudio' --version)\" = 'Rung Studio $version' ]"
example=$prefix/share/rungstudio/examples/vigor/traffic-light.rung
check "rungstudio-cli check of an installed example" "$cli" check "$example"
# The catalogues are compiled into the programs: Hungarian is found wherever they are installed.
check "the translations are found (--lang hu, --lang it)" \
    bash -c "en=\$('$cli' --lang en check '$work/none.rung' 2>&1);
             [ \"\$('$cli' --lang hu check '$work/none.rung' 2>&1)\" != \"\$en\" ] &&
             [ \"\$('$cli' --lang it check '$work/none.rung' 2>&1)\" != \"\$en\" ]"
check "the examples and the guide beside the program (bin/../share)" \
    test -d "$prefix/bin/../share/rungstudio/examples/cpm1" -a \
    -f "$prefix/bin/../share/doc/rungstudio/user-guide.html"

# ---- Desktop entry, AppStream metadata, MIME types ---------------------------------------------
share=$prefix/share
check "desktop-file-validate" desktop-file-validate "$share/applications/io.github.rungstudio.RungStudio.desktop"
check "appstreamcli validate --no-net" appstreamcli validate --no-net \
    "$share/metainfo/io.github.rungstudio.RungStudio.metainfo.xml"
check "xmllint on the MIME file" xmllint --noout "$share/mime/packages/io.github.rungstudio.RungStudio.xml"
check "update-mime-database takes the MIME file" update-mime-database "$share/mime"
mkdir -p "$work/files"
cp "$example" "$work/files/plant.rung"
cp "$example" "$work/files/mailed-without-extension" # the magic: the project's first key
"$cli" convert "$example" --to ladder -o "$work/files/plant.ladder"
echo '{"stations": []}' >"$work/files/plant.rungnet"
echo 'program plant.rung' >"$work/files/plant.rungtest"
filetype_is() { # the type a desktop finds for a file (xdg-mime, shared-mime-info's database)
    local found
    found=$(XDG_DATA_DIRS="$share:/usr/share" XDG_DATA_HOME="$work/no-user-data" xdg-mime query filetype "$1")
    [ "$found" = "$2" ] || { echo "$1: $found, not $2"; return 1; }
}
check ".rung is a Rung Studio project" filetype_is "$work/files/plant.rung" application/x-rungstudio-project
check "a project without its extension too (magic)" \
    filetype_is "$work/files/mailed-without-extension" application/x-rungstudio-project
check ".ladder is a ladder text" filetype_is "$work/files/plant.ladder" text/x-rungstudio-ladder
check ".rungnet is a network" filetype_is "$work/files/plant.rungnet" application/x-rungstudio-network
check ".rungtest is a test scenario" filetype_is "$work/files/plant.rungtest" text/x-rungstudio-test

# ---- Man pages against --help ------------------------------------------------------------------
# The options a text names, as tests/cli/man_page.h reads them.
options_in() { grep -oP '(?<![\w-])(--?[a-z][a-z-]*[a-z]|-[a-z])(?!\w)' | sort -u; }
man_options() { zcat "$1" | grep -v '^\.\\"' | sed 's/\\-/-/g' | options_in; }
same_options() { # same_options MANPAGE PROGRAM
    diff <(man_options "$1") <(LANG=C LC_ALL=C QT_QPA_PLATFORM=offscreen "$2" --help | options_in)
}
for language in "" hu/ it/; do
    check "${language}rungstudio-cli.1 names the options of rungstudio-cli --help" \
        same_options "$share/man/${language}man1/rungstudio-cli.1.gz" "$cli"
    check "${language}rungstudio.1 names the options of rungstudio --help" \
        same_options "$share/man/${language}man1/rungstudio.1.gz" "$prefix/bin/rungstudio"
done
check "the man pages read without a groff warning" bash -c "
    for page in '$share'/man/man1/*.1.gz '$share'/man/*/man1/*.1.gz; do
        out=\$(LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -l \"\$page\" 2>&1 >/dev/null)
        [ -z \"\$out\" ] || { echo \"\$page: \$out\"; exit 1; }
    done"

# ---- Bash completion -----------------------------------------------------------------------------
complete_words() { # complete_words WORD...: what the completion offers for the last word
    bash -c '
        source /usr/share/bash-completion/bash_completion
        source "$0"
        COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1))
        COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
        _rungstudio_cli rungstudio-cli "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD-1]}"
        printf "%s\n" "${COMPREPLY[@]}"' "$RUNG_COMPLETION" "$@"
}
export RUNG_COMPLETION=$share/bash-completion/completions/rungstudio-cli
export -f complete_words
check "completion: the commands" bash -c "[ \"\$(complete_words rungstudio-cli s | sort | tr '\n' ' ')\" = 'serve show simulate ' ]"
check "completion: an option of serve" bash -c "complete_words rungstudio-cli serve x.rung --pro | grep -qx -- --protocol"
check "completion: serve's --pty takes no value" bash -c "complete_words rungstudio-cli serve x.rung --pty --st | grep -qx -- --station"
check "completion: the targets" bash -c "[ \"\$(complete_words rungstudio-cli check x.il --target '' | tr '\n' ' ')\" = 'vpc vigor cpm1 pl110 ' ]"

# ---- The package installed by dpkg (--dpkg) ----------------------------------------------------
if $dpkg_too; then
    [ "$(id -u)" -eq 0 ] || { echo "--dpkg installs the package: run as root" >&2; exit 2; }
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$deb" >"$work/dpkg.log" 2>&1 ||
        { cat "$work/dpkg.log"; bad "apt-get install $deb"; }
    check "dpkg: the menu entry in mimeinfo.cache (update-desktop-database's trigger)" \
        grep -q 'application/x-rungstudio-project=.*io.github.rungstudio.RungStudio.desktop' \
        /usr/share/applications/mimeinfo.cache
    check "dpkg: the icons in the hicolor theme" \
        test -f /usr/share/icons/hicolor/48x48/apps/io.github.rungstudio.RungStudio.png \
        -a -f /usr/share/icons/hicolor/scalable/mimetypes/application-x-rungstudio-project.svg
    check "dpkg: the file type in the MIME database (update-mime-database's trigger)" \
        bash -c "grep -q 'x-rungstudio-project' /usr/share/mime/globs2 && [ \"\$(xdg-mime query filetype '$work/files/plant.rung')\" = application/x-rungstudio-project ]"
    check "dpkg: the man page (man-db's trigger)" bash -c "man -w rungstudio-cli | grep -q /usr/share/man"
    check "dpkg: rungstudio-cli on the PATH" bash -c "[ \"\$(rungstudio-cli --version)\" = 'rungstudio-cli $version' ]"
    DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq rungstudio >>"$work/dpkg.log" 2>&1
    check "dpkg: removed again, and its file type with it" \
        bash -c "! grep -q 'x-rungstudio-project' /usr/share/mime/globs2 && [ ! -e /usr/bin/rungstudio ]"
fi

echo "package checks: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
