#!/usr/bin/env bash
# A case run whose library cannot be loaded fails with the reason. OpenFOAM v1912 only
# warns ("Unknown function type dropletFiberCollision") and runs the case without the
# function object, exit 0; the project's runner (runCase.sh, through
# bin/checkFunctionObjectRan) must fail instead, saying that the function object did
# not run and the likely cause; so must the tutorial's Allrun (through the
# regression check). The library is hidden: FOAM_USER_LIBBIN is an empty
# folder and no folder of LD_LIBRARY_PATH holds libdropletFiber.so.
# Usage: checkLibraryNotLoaded.sh CASE_DIR WORK_DIR [serial|parallel]
set -uo pipefail
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
loadFoamEnvironment
caseDir="$1"; work="$2"; mode="${3:-serial}"
rm -rf "$work"; mkdir -p "$work/emptyLibbin"

export FOAM_USER_LIBBIN="$work/emptyLibbin"
withoutLibrary=""
IFS=: read -r -a libraryPath <<< "${LD_LIBRARY_PATH:-}"
for dir in "${libraryPath[@]}"; do
    [ -e "$dir/libdropletFiber.so" ] || withoutLibrary="${withoutLibrary:+$withoutLibrary:}$dir"
done
export LD_LIBRARY_PATH="$FOAM_USER_LIBBIN${withoutLibrary:+:$withoutLibrary}"

"$here/runCase.sh" "$caseDir" "$work/case" "$mode" > "$work/runCase.log" 2>&1
status=$?
sed 's/^/    | /' "$work/runCase.log" | tail -20
check "[ $status -ne 0 ]" "runCase.sh passed a run whose library was not loaded"
check 'grep -q "Unknown function type dropletFiberCollision" "$work/case/log.pimpleFoam"' \
    "the solver's log does not show the library missing (was it found after all?)"
check 'grep -q "the dropletFiberCollision function object did not run" "$work/runCase.log"' \
    "runCase.sh does not say that the function object did not run"
check 'grep -q "Unknown function type dropletFiberCollision" "$work/runCase.log"' \
    "runCase.sh does not show the log's warning"
check 'grep -q "nor on LD_LIBRARY_PATH" "$work/runCase.log" && grep -q "$FOAM_USER_LIBBIN" "$work/runCase.log"' \
    "runCase.sh does not give the likely cause (library not in FOAM_USER_LIBBIN)"
# The same check from POSIX sh, as the tutorial's /bin/sh Allrun calls it
sh "$here/../../bin/checkFunctionObjectRan" "$work/case" > /dev/null 2>&1
check "[ $? -eq 1 ]" "bin/checkFunctionObjectRan under sh does not fail on that run"
# The tutorial's Allrun (/bin/sh) through the regression check (a few seconds
# without the function object)
"$here/../regression/channelSpray/check.sh" "$mode" "$work/tutorial" > "$work/tutorial.log" 2>&1
status=$?
check "[ $status -ne 0 ]" "the regression check passed a tutorial run whose library was not loaded"
check 'grep -q "the dropletFiberCollision function object did not run" "$work/tutorial.log"' \
    "the tutorial's Allrun does not say that the function object did not run"
checkSummary
