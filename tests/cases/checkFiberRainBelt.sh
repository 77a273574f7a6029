#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkFiberRainBelt.sh - bad fibers.laydown entries stop the run at the start
# with a FatalIOError naming the entry (and the dictionary,
# controlDict.functions.dropletFiber.fibers.laydown), before the first step and
# without a crash; the same belt given as point, normal and width lays the
# patch's mat.
#
# Usage: checkFiberRainBelt.sh CASE_DIR WORK_DIR
#   The fiberRain case with its laydown entry replaced, serial, to 4 steps:
#   a patch that does not exist; cell 0 and -0.01; a velocity out of the belt's
#   plane; patch together with point and normal; width with patch; a non-planar
#   patch (walls: five faces of the box); neither patch nor point; a key not
#   known; a zero normal. Then the belt as point (0.1 0 0.05), normal (0 -1 0),
#   width 0.1 (the patch bottom's centre, normal and extent) run to 0.125: the
#   hand's fibers and mat (checkFiberRain.py). Then footprint centre to 0.5: each
#   fiber whole in its centre's cell (checkFiberRainCentre.py). Then the populations spread (P59)
#   to 0.5: the glass conserved, every complete row G (checkFiberRainSpread.py).
#------------------------------------------------------------------------------
set -uo pipefail
caseDir="$(cd "$1" && pwd)"; work="$2"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
# shellcheck disable=SC1091
. "$here/lib/editFile.sh"
prepareCaseCopy "$caseDir" "$work"
cp system/controlDict system/controlDict.good
belt="velocity (0.256 0 0); cell 0.01;"

# setLaydown LAYDOWN: the laydown block replaced by `laydown LAYDOWN`, the rest of the
# file as it is (foamDictionary -set would rewrite it all to 6 digits: the injectors'
# startTime 2^-10 s and directions with it)
setLaydown() {
    cp system/controlDict.good system/controlDict
    edit system/controlDict 'laydown\s*\{[^{}]*\}' "laydown $1"
}

# expectError LAYDOWN PATTERN: fibers.laydown set to LAYDOWN, PATTERN (an extended
# regular expression) expected in the FatalIOError, with the dictionary's name
expectError() {
    local laydown="$1" pattern="$2" status=0
    setLaydown "$laydown"
    sed -i "s/^endTime .*/endTime         0.00390625;/" system/controlDict
    timeout 60 pimpleFoam > log.bad 2>&1 || status=$?
    expectFatalIOError "$status" log.bad "$pattern" "laydown $laydown"
    check "grep -q 'controlDict.functions.dropletFiber.fibers.laydown' log.bad" \
        "laydown $laydown: the error does not name the dictionary"
    check "! grep -q -E '^Time = |printStack|Segmentation fault|core dumped' log.bad" \
        "laydown $laydown: a step ran or the run crashed"
}

expectError "{ patch nosuch; $belt }" \
    "Entry 'patch' names patch 'nosuch', which does not exist: allowed are the mesh's patches 2\(bottom walls\)"
expectError "{ patch bottom; velocity (0.256 0 0); cell 0; }" "Entry 'cell' is 0: allowed are finite values > 0"
expectError "{ patch bottom; velocity (0.256 0 0); cell -0.01; }" \
    "Entry 'cell' is -0.01: allowed are finite values > 0"
expectError "{ patch bottom; velocity (0.256 0.01 0); cell 0.01; }" \
    "Entry 'velocity' is \(0.256 0.01 0\), which leaves the belt's plane \(normal \(0 -1 0\)\) at 0.01 m/s"
expectError "{ patch bottom; point (0.1 0 0.05); normal (0 -1 0); $belt }" \
    "Entry 'laydown' needs the belt as 'patch', or as 'point', 'normal' and 'width', not both"
expectError "{ patch bottom; width 0.1; $belt }" \
    "Entry 'width' is for a belt given as point and normal: with 'patch' the belt's width is the patch's extent"
expectError "{ patch walls; $belt }" "Entry 'patch' names patch 'walls', which is not planar"
expectError "{ $belt }" "Entry 'laydown' needs the belt as 'patch', or as 'point', 'normal' and 'width'\.$"
expectError "{ patch bottom; $belt speed 0.256; }" \
    "Entry 'speed' in dictionary '[^']*laydown' is not known: allowed are patch, point, normal, width, velocity, cell"
expectError "{ point (0.1 0 0.05); normal (0 0 0); width 0.1; $belt }" "Entry 'normal' is \(0 0 0\)"
expectError "{ point (0.1 0 0.05); normal (0 1 0); width 0.1; $belt }" \
    "Entry 'normal' \(0 1 0\): the belt's normal points into the air"
expectError "{ point (0.1 0 0.05); normal (0 -1 0); width 0.1; velocity (0.256 0 0); cell 0.1; }" \
    "Entry 'cell' is 0.1 m, not smaller than the belt's width 0.1 m"

# expectWarning LAYDOWN PATTERN: runs a few steps with a warning matching PATTERN
expectWarning() {
    local laydown="$1" pattern="$2" status=0
    setLaydown "$laydown"
    sed -i "s/^endTime .*/endTime         0.00390625;/" system/controlDict
    rm -rf postProcessing
    timeout 60 pimpleFoam > log.warn 2>&1 || status=$?
    foamListTimes -rm > /dev/null 2>&1
    check "[ $status -eq 0 ] && grep -q -E -- \"$pattern\" log.warn" \
        "laydown $laydown: no warning '$pattern' (exit $status)"
}
expectWarning "{ point (0.1 -1 0.05); normal (0 -1 0); width 0.1; $belt }" \
    "the belt's plane through \(0.1 -1 0.05\) lies 1 m beyond the mesh's bounds: no fiber reaches it"
expectWarning "{ patch bottom; $belt steadyFrom 1; }" \
    "Entry 'steadyFrom' is 1 s, not before the run's endTime 0.00390625 s: no row of the mat will be complete"
expectWarning "{ patch bottom; velocity (30 0 0); cell 0.01; }" \
    "Entry 'velocity': the belt's speed is 30 m/s: plausible are 0.001 to 10 m/s; a speed in m/min given in m/s"

# The same belt as a plane: the hand's fibers and mat (the stopped runs' tables removed)
rm -rf postProcessing
setLaydown "{ point (0.1 0 0.05); normal (0 -1 0); width 0.1; $belt }"
sed -i "s/^endTime .*/endTime         0.125;/" system/controlDict
timeout 120 pimpleFoam > log.pimpleFoam 2>&1
check "[ $? -eq 0 ] && tail -n 3 log.pimpleFoam | grep -q '^End'" "the belt as a plane: the run failed"
check "grep -q 'laydown: belt through (0.1 0 0.05), normal (0 -1 0), velocity (0.256 0 0) m/s, across -0.05 to 0.05 m' log.pimpleFoam" \
    "the belt as a plane: the log does not give its settings"
check "'$PY' '$here/checkFiberRain.py' . > log.check" "the belt as a plane: not the hand's mat (log.check)"
tail -1 log.check

# Each fiber whole in its centre's cell (footprint centre): the map before P58
# (checkFiberRainCentre.py)
rm -rf postProcessing 0.* [1-9]*
setLaydown "{ patch bottom; $belt footprint centre; }"
sed -i "s/^endTime .*/endTime         0.5;/" system/controlDict
timeout 120 pimpleFoam > log.pimpleFoam 2>&1
check "[ $? -eq 0 ] && tail -n 3 log.pimpleFoam | grep -q '^End'" "footprint centre: the run failed"
check "grep -q 'fibers whole at their centres' log.pimpleFoam" "footprint centre: the log does not say so"
check "'$PY' '$here/checkFiberRainCentre.py' . > log.checkCentre" \
    "footprint centre: not the map of whole fibers at their centres (log.checkCentre)"
tail -1 log.checkCentre

# The populations spread (P59; the case's own collision.spread off removed): the glass
# conserved, every complete row the uniform rain's G (checkFiberRainSpread.py)
rm -rf postProcessing 0.* [1-9]*
setLaydown "{ patch bottom; $belt populations spread; }"
edit system/controlDict 'collision\s*\{\s*spread\s*\{[^{}]*\}\s*\}' ''
timeout 120 pimpleFoam > log.pimpleFoam 2>&1
check "[ $? -eq 0 ] && tail -n 3 log.pimpleFoam | grep -q '^End'" "populations spread: the run failed"
check "grep -q 'populations spread (P59)' log.pimpleFoam" "populations spread: the log does not say so"
check "'$PY' '$here/checkFiberRainSpread.py' . > log.checkSpread" \
    "populations spread: the rain's mat not conserved (log.checkSpread)"
tail -1 log.checkSpread
checkSummary
