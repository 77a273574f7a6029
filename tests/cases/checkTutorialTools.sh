#!/usr/bin/env bash
#------------------------------------------------------------------------------
# How a tutorial's scripts find the project's run functions and tools, each
# tutorial copied to a new folder outside the project:
# - no dropletFiberRunFunctions on PATH and no DROPLETFIBER_DIR: Allrun and
#   Allparaview stop at once (exit 1, nothing run: no log.blockMesh) saying that
#   ./Allwmake installs them and what DROPLETFIBER_DIR does;
# - DROPLETFIBER_DIR naming a folder without them: stops at once, naming it;
# - the run functions found but not the tools (on PATH, or in DROPLETFIBER_DIR's
#   bin/): stops at once, naming the missing tool, saying what to do;
# - DROPLETFIBER_DIR naming a project folder: its bin/ is used instead of PATH's
#   (channelSpray -short run to the end with its run functions and stand-ins of the
#   tools there that note being called);
# - the ParaView launcher (Allparaview, dropletFiberRunFunctions'
#   dropletFiberParaView) with stand-ins of paraview, pvbatch and xvfb-run that note
#   how they are called: the GUI on the tutorial's folder, -batch headless with the
#   case and the screenshot, on a virtual display only where there is no DISPLAY,
#   the project's dropletFiberParaView.py from PATH or DROPLETFIBER_DIR, and a clear
#   stop without it. (tests/report checks the script itself in ParaView.)
# - the forming hood's Python helpers (reportPackage.py) take the report's modules
#   beside the report on PATH, or the project's with DROPLETFIBER_DIR, and stop
#   saying what to do without them.
# That the tools found on PATH are used, and work, the regression runs show
# (tests/regression: each a copy run without DROPLETFIBER_DIR).
#
# Usage: checkTutorialTools.sh WORK   (WORK: a scratch folder, replaced)
#------------------------------------------------------------------------------
set -euo pipefail
work="$1"
root="$(cd "${0%/*}/../.." && pwd)"
# shellcheck disable=SC1091
. "$root/bin/functions.sh"
loadFoamEnvironment
rm -rf "$work"
mkdir -p "$work"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/dropletFiber-tools.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
failed=0
check() {
    local what="$1"; shift
    if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; failed=1; fi
}

# PATH without any folder that has the run functions or tools (the OpenFOAM
# utilities stay); a folder with the run functions alone
bare=
IFS=: read -r -a folders <<< "$PATH"
for folder in "${folders[@]}"; do
    [ -e "$folder/dropletFiberReport" ] || [ -e "$folder/checkFunctionObjectRan" ] \
        || [ -e "$folder/dropletFiberRunFunctions" ] || bare="$bare${bare:+:}$folder"
done
functionsOnly="$scratch/functionsOnly"
mkdir -p "$functionsOnly/bin"
install -m 644 "$root/bin/dropletFiberRunFunctions" "$functionsOnly/bin/"

for tutorial in channelSpray channelSprayRAS formingHood; do
    copy="$scratch/$tutorial"
    cp -r "$root/tutorials/$tutorial" "$copy"
    (cd "$copy" && ./Allclean > /dev/null)
    set +e
    (cd "$copy" && env -u DROPLETFIBER_DIR PATH="$bare" ./Allrun -short > "$work/$tutorial.noTools.log" 2>&1)
    status=$?
    set -e
    sed 's/^/    /' "$work/$tutorial.noTools.log"
    check "$tutorial without the tools: exit 1 (got $status)" test "$status" -eq 1
    check "$tutorial without the tools: nothing run" test ! -e "$copy/log.blockMesh"
    check "$tutorial without the tools: says ./Allwmake installs them and names DROPLETFIBER_DIR" \
        grep -q "dropletFiberRunFunctions not found on PATH.*Allwmake.*DROPLETFIBER_DIR" "$work/$tutorial.noTools.log"
    set +e
    (cd "$copy" && DROPLETFIBER_DIR="$scratch/noProject" ./Allrun -short > "$work/$tutorial.wrongDir.log" 2>&1)
    status=$?
    set -e
    check "$tutorial with DROPLETFIBER_DIR=$scratch/noProject: exit 1 naming it (got $status)" eval \
        '[ "$status" -eq 1 ] && grep -q "dropletFiberRunFunctions not found in $scratch/noProject/bin (DROPLETFIBER_DIR)" "$work/$tutorial.wrongDir.log"'
    check "$tutorial with DROPLETFIBER_DIR=$scratch/noProject: nothing run" test ! -e "$copy/log.blockMesh"

    # the run functions found, the tools not: the lookup of dropletFiberRunFunctions
    set +e
    (cd "$copy" && env -u DROPLETFIBER_DIR PATH="$functionsOnly/bin:$bare" ./Allrun -short \
        > "$work/$tutorial.functionsOnly.log" 2>&1)
    status=$?
    set -e
    check "$tutorial with the run functions but no tools on PATH: exit 1 (got $status), nothing run" \
        eval '[ "$status" -eq 1 ] && [ ! -e "$copy/log.blockMesh" ]'
    check "$tutorial with the run functions but no tools on PATH: names the tool, ./Allwmake and DROPLETFIBER_DIR" \
        grep -q "checkFunctionObjectRan not found on PATH.*Allwmake.*DROPLETFIBER_DIR" "$work/$tutorial.functionsOnly.log"
    set +e
    (cd "$copy" && DROPLETFIBER_DIR="$functionsOnly" ./Allrun -short > "$work/$tutorial.functionsOnlyDir.log" 2>&1)
    status=$?
    set -e
    check "$tutorial with DROPLETFIBER_DIR=<the run functions alone>: exit 1 naming the tool (got $status), nothing run" \
        eval '[ "$status" -eq 1 ] && [ ! -e "$copy/log.blockMesh" ] && grep -q "DROPLETFIBER_DIR is set ($functionsOnly) but has no bin/checkFunctionObjectRan" "$work/$tutorial.functionsOnlyDir.log"'
    set +e
    (cd "$scratch" && env -u DROPLETFIBER_DIR PATH="$bare" "$copy/Allparaview" -batch > "$work/$tutorial.paraviewNoTools.log" 2>&1)
    status=$?
    set -e
    check "$tutorial's Allparaview without the run functions: exit 1 (got $status), saying what to do" eval \
        '[ "$status" -eq 1 ] && grep -q "dropletFiberRunFunctions not found on PATH.*Allwmake.*DROPLETFIBER_DIR" "$work/$tutorial.paraviewNoTools.log"'
done

# DROPLETFIBER_DIR wins over PATH: the project's run functions (saying whose they
# are when sourced) and stand-ins of the tools in a project folder of its own
project="$scratch/project"
mkdir -p "$project/bin"
for tool in checkFunctionObjectRan dropletFiberReport; do
    printf '#!/bin/sh\necho "%s $*" >> "%s/called"\n' "$tool" "$project" > "$project/bin/$tool"
    chmod +x "$project/bin/$tool"
done
cp "$root/bin/dropletFiberParaView.py" "$project/bin/"
{ cat "$root/bin/dropletFiberRunFunctions"; echo "echo \"run functions of $project\""; } \
    > "$project/bin/dropletFiberRunFunctions"
copy="$scratch/channelSpray"
set +e
(cd "$copy" && DROPLETFIBER_DIR="$project" ./Allrun -short > "$work/override.log" 2>&1)
status=$?
set -e
tail -5 "$work/override.log" | sed 's/^/    /'
check "DROPLETFIBER_DIR=<a project>: channelSpray -short runs (exit $status)" test "$status" -eq 0
check "DROPLETFIBER_DIR=<a project>: its run functions are the ones sourced" \
    grep -q -x "run functions of $project" "$work/override.log"
check "DROPLETFIBER_DIR=<a project>: its tools are the ones used" \
    grep -q -x "dropletFiber tools: $project/bin/checkFunctionObjectRan, $project/bin/dropletFiberReport" "$work/override.log"
check "DROPLETFIBER_DIR=<a project>: both called ($(tr '\n' ';' < "$project/called" 2> /dev/null))" eval \
    'grep -q "^checkFunctionObjectRan log.pimpleFoam$" "$project/called" && grep -q "^dropletFiberReport -o channelSpray .$" "$project/called"'

# The forming hood's Python helpers find the report's modules as Allrun finds the
# report, and say what to do without them
hood="$scratch/formingHood"
set +e
(cd "$scratch" && env -u DROPLETFIBER_DIR PATH="$bare" /usr/bin/python3 "$hood/hoodBalance.py" "$hood" log.sprayFoam \
    > "$work/hoodNoReport.log" 2>&1)
status=$?
set -e
check "hoodBalance.py without the report on PATH: exit 1 (got $status), naming it, ./Allwmake and DROPLETFIBER_DIR" eval \
    '[ "$status" -eq 1 ] && grep -q "dropletFiberReport not found on PATH.*" "$work/hoodNoReport.log" && grep -q "Allwmake" "$work/hoodNoReport.log" && ! grep -q Traceback "$work/hoodNoReport.log"'
for projectDir in "$project" "$root"; do
    found="$(cd "$scratch" && DROPLETFIBER_DIR="$projectDir" /usr/bin/python3 -c \
        'import sys; sys.path.insert(0, sys.argv[1]); import reportPackage, caseOutputs; print(caseOutputs.__file__)' "$hood" 2>&1)" || true
    if [ "$projectDir" = "$root" ]; then
        check "the hood's helpers with DROPLETFIBER_DIR=<this project>: its tools/dropletFiberReport modules ($found)" \
            test "$found" = "$root/bin/../tools/dropletFiberReport/caseOutputs.py"
    else
        check "the hood's helpers with DROPLETFIBER_DIR=<a project with a report but not its modules>: stop naming where they looked ($found)" \
            eval '[[ "$found" == *"the report'"'"'s modules are neither in $project/bin/dropletFiberPython nor in the project'"'"'s"*"Allwmake"* ]]'
    fi
done
found="$(cd "$scratch" && env -u DROPLETFIBER_DIR /usr/bin/python3 -c \
    'import sys; sys.path.insert(0, sys.argv[1]); import reportPackage, caseOutputs; print(caseOutputs.__file__)' "$hood" 2>&1)" || true
check "the hood's helpers on PATH: the modules installed beside the report ($found)" \
    test "$found" = "$(dirname "$(command -v dropletFiberReport)")/dropletFiberPython/caseOutputs.py"

# The ParaView launcher: stand-ins of ParaView's programs that note their arguments
# and folder, the tutorial's Allparaview run from another folder
standIns="$scratch/paraviewStandIns"
mkdir -p "$standIns"
for program in paraview pvbatch xvfb-run; do
    printf '#!/bin/sh\necho "%s $* (in $PWD)" >> "%s/called"\n' "$program" "$standIns" > "$standIns/$program"
    chmod +x "$standIns/$program"
done
# shellcheck disable=SC2034  # used in the checks' eval
installed="$(dirname "$(command -v dropletFiberReport)")"
viewed="$scratch/channelSpray"
paraviewRun() {  # paraviewRun LABEL ENV... -- ARGS...: Allparaview's exit status and calls in $work/LABEL.*
    local label="$1"; shift
    local environment=()
    while [ "$1" != "--" ]; do environment+=("$1"); shift; done
    shift
    rm -f "$standIns/called"
    set +e
    (cd "$scratch" && env "${environment[@]}" "$viewed/Allparaview" "$@" > "$work/$label.log" 2>&1)
    echo "$?" > "$work/$label.status"
    set -e
    cat "$standIns/called" > "$work/$label.called" 2> /dev/null || : > "$work/$label.called"
    sed 's/^/    /' "$work/$label.log" "$work/$label.called"
}
onPath="PATH=$standIns:$PATH"
paraviewRun paraviewGUI -u DROPLETFIBER_DIR "$onPath" DISPLAY=:7 --
check "Allparaview: ParaView's GUI runs the installed dropletFiberParaView.py in the tutorial's folder" eval \
    '[ "$(cat "$work/paraviewGUI.status")" = 0 ] && [ "$(cat "$work/paraviewGUI.called")" = "paraview --script=$installed/dropletFiberParaView.py (in $viewed)" ]'
paraviewRun paraviewBatch -u DROPLETFIBER_DIR "$onPath" DISPLAY=:7 -- -batch
check "Allparaview -batch with a display: pvbatch on the case, writing channelSpray.paraview.png there" eval \
    '[ "$(cat "$work/paraviewBatch.status")" = 0 ] && [ "$(cat "$work/paraviewBatch.called")" = "pvbatch $installed/dropletFiberParaView.py $viewed --screenshot $viewed/channelSpray.paraview.png (in $viewed)" ]'
paraviewRun paraviewNoDisplay -u DROPLETFIBER_DIR -u DISPLAY "$onPath" -- -batch
check "Allparaview -batch without a display: pvbatch through xvfb-run on a 24-bit screen" eval \
    '[ "$(cat "$work/paraviewNoDisplay.status")" = 0 ] && [ "$(cat "$work/paraviewNoDisplay.called")" = "xvfb-run -a -s -screen 0 1280x1024x24 pvbatch $installed/dropletFiberParaView.py $viewed --screenshot $viewed/channelSpray.paraview.png (in $viewed)" ]'
paraviewRun paraviewProject DROPLETFIBER_DIR="$project" "$onPath" DISPLAY=:7 -- -batch
check "Allparaview with DROPLETFIBER_DIR=<a project>: that project's dropletFiberParaView.py" eval \
    '[ "$(cat "$work/paraviewProject.status")" = 0 ] && [ "$(cat "$work/paraviewProject.called")" = "pvbatch $project/bin/dropletFiberParaView.py $viewed --screenshot $viewed/channelSpray.paraview.png (in $viewed)" ]'
paraviewRun paraviewNoScript -u DROPLETFIBER_DIR "PATH=$standIns:$functionsOnly/bin:$bare" DISPLAY=:7 -- -batch
check "Allparaview without dropletFiberParaView.py on PATH: exit 1, ParaView not started, saying what to do" eval \
    '[ "$(cat "$work/paraviewNoScript.status")" = 1 ] && [ ! -s "$work/paraviewNoScript.called" ] && grep -q "dropletFiberParaView.py not found on PATH.*Allwmake.*DROPLETFIBER_DIR" "$work/paraviewNoScript.log"'
paraviewRun paraviewBadOption -u DROPLETFIBER_DIR "$onPath" -- -bogus
check "Allparaview -bogus: exit 1, ParaView not started" eval \
    '[ "$(cat "$work/paraviewBadOption.status")" = 1 ] && [ ! -s "$work/paraviewBadOption.called" ]'
exit $failed
