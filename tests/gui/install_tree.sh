#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then the installed tree moved elsewhere (so nothing
# can depend on the install prefix either) and run with the build and source trees hidden: it
# must find its presets and shaders through its own location, validate and run a preset from
# share/particle-lab, open the GUI for 3 frames with a screenshot, and carry its version, man
# page, desktop entry (desktop-file-validate clean), icon and bash completion.
# Usage: install_tree.sh <particle-lab binary in a build tree> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
BUILD=$(cd "$(dirname "$APP")" && pwd)

cmake --install "$BUILD" --prefix "$WORK/prefix" >"$WORK/install.txt" || fail "install failed: $(cat "$WORK/install.txt")"
mv "$WORK/prefix" "$WORK/moved"
P=$WORK/moved
for f in bin/particle-lab share/particle-lab/presets/default.json share/particle-lab/shaders/sphere.frag \
         share/applications/particle-lab.desktop share/icons/hicolor/scalable/apps/particle-lab.svg \
         share/man/man1/particle-lab.1 share/bash-completion/completions/particle-lab share/doc/particle_lab/LICENSE; do
    [ -s "$P/$f" ] || fail "not installed: $f"
done
desktop-file-validate "$P/share/applications/particle-lab.desktop" || fail "desktop entry not valid"
grep -q '^\.SH OPTIONS' "$P/share/man/man1/particle-lab.1" || fail "man page has no OPTIONS section"
! grep -qaF "$SRC" "$P/bin/particle-lab" || fail "the installed binary holds the source path $SRC"
! grep -qaF "$BUILD" "$P/bin/particle-lab" || fail "the installed binary holds the build path $BUILD"

version=$(sed -n 's/^project(particle_lab VERSION \([0-9.]*\).*/\1/p' "$SRC/CMakeLists.txt")
[ "$("$P/bin/particle-lab" --version)" = "particle-lab $version" ] || fail "--version is not 'particle-lab $version'"

# The checks run with the source and build trees replaced by empty folders (a private mount
# namespace) when the system allows it; otherwise the path checks above are what guard.
cat >"$WORK/installed.sh" <<SCRIPT
set -euo pipefail
cd "$WORK"
[ ! -e "$SRC/presets/default.json" ] || [ "\${HIDDEN:-0}" = 0 ]
"$P/bin/particle-lab" validate "$P/share/particle-lab/presets/drag_models.json"
"$P/bin/particle-lab" run "$P/share/particle-lab/presets/default.json" --duration 0.5 --out "$WORK/traj.csv"
timeout 60 "$P/bin/particle-lab" --frames 3 --screenshot "$WORK/shot.png" --dump-state "$WORK/state.json"
SCRIPT
if unshare --mount --map-root-user true 2>/dev/null; then
    HIDDEN=1 unshare --mount --map-root-user bash -c \
        "mount -t tmpfs none '$BUILD' && mount -t tmpfs none '$SRC' && bash '$WORK/installed.sh'" \
        >"$WORK/out.txt" 2>&1 || fail "installed binary failed with the trees hidden: $(cat "$WORK/out.txt")"
    echo "ran with the source and build trees hidden"
else
    bash "$WORK/installed.sh" >"$WORK/out.txt" 2>&1 || fail "installed binary failed: $(cat "$WORK/out.txt")"
    echo "no mount namespace here: ran with the trees in place (no path to them is compiled in)"
fi
[ "$(wc -l <"$WORK/traj.csv")" -gt 2 ] || fail "no trajectory written"
[ -s "$WORK/shot.png" ] || fail "no screenshot"
json_check "$WORK/state.json" 'd["preset"].endswith("share/particle-lab/presets/default.json")' \
    "the GUI did not open the installed default preset"
echo "OK"
