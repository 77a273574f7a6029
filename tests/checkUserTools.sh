#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The user-facing tools are installed like OpenFOAM's own utilities
# (bin/functions.sh: userTools, installUserTools, removeUserTools):
# 1. ./Allwmake has installed them: each in $FOAM_USER_APPBIN equal to the
#    project's file, the report's modules in $FOAM_USER_APPBIN/dropletFiberPython
#    equal to tools/dropletFiberReport's, and PATH finds each there; Allwmake and
#    Allclean install and remove them in $FOAM_USER_APPBIN.
# 2. Installed into a new folder, the report runs from there with nothing of the
#    project beside it (a missing case: exit 2 naming it, no traceback: its modules
#    found in its own folder); the run functions (dropletFiberRunFunctions),
#    sourced by sh from there, find the tools installed beside them on PATH (the
#    ParaView script, not executable, too); removed, none of them is left and the
#    folder's other files stay.
#
# Usage: checkUserTools.sh WORK   (WORK: a scratch folder, replaced)
# Needs the OpenFOAM environment ./Allwmake built in (loaded here as the tests do).
#------------------------------------------------------------------------------
set -euo pipefail
work="$1"
root="$(cd "${0%/*}/.." && pwd)"
# shellcheck disable=SC1091
. "$root/bin/functions.sh"
loadFoamEnvironment
failed=0
check() {
    local what="$1"; shift
    if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; failed=1; fi
}
same() { cmp -s "$1" "$2"; }
onPath() { [ "$(command -v "$1")" = "$FOAM_USER_APPBIN/$1" ]; }

# 1. What ./Allwmake installed
stale="run ./Allwmake again: it installs them"
for tool in "${userTools[@]}"; do
    check "$tool in \$FOAM_USER_APPBIN ($FOAM_USER_APPBIN) is the project's ($stale)" \
        same "$root/bin/$tool" "$FOAM_USER_APPBIN/$tool"
done
check "dropletFiberReport and checkFunctionObjectRan are run from \$FOAM_USER_APPBIN on PATH" \
    eval 'onPath dropletFiberReport && onPath checkFunctionObjectRan'
check "dropletFiberParaView.py and dropletFiberRunFunctions (a ParaView script, sourced functions: not commands) are in a folder of PATH" \
    eval '[[ ":$PATH:" == *":$FOAM_USER_APPBIN:"* ]]'
for module in "$root"/tools/dropletFiberReport/*.py; do
    check "the report's module ${module##*/} installed in dropletFiberPython/ ($stale)" \
        same "$module" "$FOAM_USER_APPBIN/$userToolsModules/${module##*/}"
done
check "no module in dropletFiberPython/ that the project no longer has" eval \
    '[ "$(ls "$FOAM_USER_APPBIN/$userToolsModules" | grep -c "\.py$")" = "$(ls "$root"/tools/dropletFiberReport/*.py | wc -l)" ]'
check "Allwmake installs them in \$FOAM_USER_APPBIN" grep -q '^installUserTools "$FOAM_USER_APPBIN"$' "$root/Allwmake"
check "Allclean removes them from \$FOAM_USER_APPBIN" grep -q '^ *removeUserTools "$FOAM_USER_APPBIN"$' "$root/Allclean"

# 2. Installed elsewhere, run from there, removed
rm -rf "$work"
mkdir -p "$work/bin"
echo "another program" > "$work/bin/otherProgram"
installUserTools "$work/bin"
for tool in "${userTools[@]}"; do
    check "installUserTools: $tool installed" test -f "$work/bin/$tool"
done
check "installUserTools: the commands are executable" \
    eval 'test -x "$work/bin/dropletFiberReport" && test -x "$work/bin/checkFunctionObjectRan"'
# The run functions as a tutorial's script uses them: sourced by sh from PATH
found="$(cd "$work" && env -u DROPLETFIBER_DIR -u USER PATH="$work/bin:/usr/bin:/bin" sh -c \
    '. dropletFiberRunFunctions && dropletFiberTool dropletFiberReport && dropletFiberTool checkFunctionObjectRan && dropletFiberTool dropletFiberParaView.py' 2>&1)" || true
check "the installed run functions, sourced by sh, find the tools beside them (got: $(echo "$found" | tr "\n" " "))" \
    test "$found" = "$work/bin/dropletFiberReport
$work/bin/checkFunctionObjectRan
$work/bin/dropletFiberParaView.py"
set +e
(cd "$work" && env -u DROPLETFIBER_DIR -u USER "$work/bin/dropletFiberReport" "$work/noCase") > "$work/report.log" 2>&1
status=$?
set -e
cat "$work/report.log"
check "the installed report runs from its folder: exit 2 on a missing case (got $status)" test "$status" -eq 2
check "... naming it" grep -q "no case folder" "$work/report.log"
check "... without a traceback (its modules found beside it)" eval '! grep -q Traceback "$work/report.log"'
check "the installed checkFunctionObjectRan runs: exit 1 on a missing log" \
    eval '! "$work/bin/checkFunctionObjectRan" "$work/noLog" 2> /dev/null'
removeUserTools "$work/bin"
check "removeUserTools: nothing of them left (left: $(ls -A "$work/bin" | tr '\n' ' '))" \
    eval '[ "$(ls -A "$work/bin")" = otherProgram ]'
exit $failed
