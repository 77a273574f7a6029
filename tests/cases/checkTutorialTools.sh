#!/usr/bin/env bash
#------------------------------------------------------------------------------
# How a tutorial's Allrun finds the project's tools, each tutorial copied to a new
# folder outside the project:
# - no tool on PATH and no DROPLETFIBER_DIR: Allrun stops at once (exit 1, nothing
#   run: no log.blockMesh) saying that ./Allwmake installs them and what
#   DROPLETFIBER_DIR does;
# - DROPLETFIBER_DIR naming a folder without the tools: stops at once, naming it;
# - DROPLETFIBER_DIR naming a project folder: its bin/ is used instead of PATH's
#   (channelSpray -short run to the end with stand-ins of the tools there that
#   note being called).
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

# PATH without any folder that has the tools (the OpenFOAM utilities stay)
bare=
IFS=: read -r -a folders <<< "$PATH"
for folder in "${folders[@]}"; do
    [ -e "$folder/dropletFiberReport" ] || [ -e "$folder/checkFunctionObjectRan" ] || bare="$bare${bare:+:}$folder"
done

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
        grep -q "checkFunctionObjectRan not found on PATH.*Allwmake.*DROPLETFIBER_DIR" "$work/$tutorial.noTools.log"
    set +e
    (cd "$copy" && DROPLETFIBER_DIR="$scratch/noProject" ./Allrun -short > "$work/$tutorial.wrongDir.log" 2>&1)
    status=$?
    set -e
    check "$tutorial with DROPLETFIBER_DIR=$scratch/noProject: exit 1 naming it (got $status)" eval \
        '[ "$status" -eq 1 ] && grep -q "DROPLETFIBER_DIR is set ($scratch/noProject) but has no bin/checkFunctionObjectRan" "$work/$tutorial.wrongDir.log"'
    check "$tutorial with DROPLETFIBER_DIR=$scratch/noProject: nothing run" test ! -e "$copy/log.blockMesh"
done

# DROPLETFIBER_DIR wins over PATH: stand-ins of the tools in a project folder of its own
project="$scratch/project"
mkdir -p "$project/bin"
for tool in checkFunctionObjectRan dropletFiberReport; do
    printf '#!/bin/sh\necho "%s $*" >> "%s/called"\n' "$tool" "$project" > "$project/bin/$tool"
    chmod +x "$project/bin/$tool"
done
copy="$scratch/channelSpray"
set +e
(cd "$copy" && DROPLETFIBER_DIR="$project" ./Allrun -short > "$work/override.log" 2>&1)
status=$?
set -e
tail -5 "$work/override.log" | sed 's/^/    /'
check "DROPLETFIBER_DIR=<a project>: channelSpray -short runs (exit $status)" test "$status" -eq 0
check "DROPLETFIBER_DIR=<a project>: its tools are the ones used" \
    grep -q -x "dropletFiber tools: $project/bin/checkFunctionObjectRan, $project/bin/dropletFiberReport" "$work/override.log"
check "DROPLETFIBER_DIR=<a project>: both called ($(tr '\n' ';' < "$project/called" 2> /dev/null))" eval \
    'grep -q "^checkFunctionObjectRan log.pimpleFoam$" "$project/called" && grep -q "^dropletFiberReport -o channelSpray .$" "$project/called"'
exit $failed
