#!/usr/bin/env bash
# Each bad dictionary entry stops the run with a FatalIOError that names the
# entry. Usage: checkBadEntries.sh CASE_DIR WORK_DIR (runs a copy)
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
prepareCaseCopy "$1" "$2"
cp system/controlDict system/controlDict.good
fo=functions/dropletFiber

# Every run starts at time 0 (startFrom latestTime: a run that went on to
# endTime would make the next one start there and end at once)
freshStart() {
    foamListTimes -rm > /dev/null 2>&1
    rm -rf postProcessing
}

# expectError ENTRY VALUE PATTERN: set ENTRY to VALUE, run, expect PATTERN
# (in a copy of $base, the good controlDict unless set)
expectError() {
    local entry="$1" value="$2" pattern="$3"
    cp "${base:-system/controlDict.good}" system/controlDict
    if [ "$value" = "REMOVE" ]; then
        foamDictionary system/controlDict -entry "$fo/$entry" -remove > /dev/null
    else
        foamDictionary system/controlDict -entry "$fo/$entry" -set "$value" > /dev/null
    fi
    freshStart
    pimpleFoam > log.bad 2>&1
    expectFatalIOError $? log.bad "$pattern" "$entry = $value"
}

expectError fibers/radius -1e-4 "Entry 'radius' is -0.0001"
expectError fibers/density abc "controlDict.functions.dropletFiber.fibers.density at line"
expectError fibers/youngsModulus REMOVE "Entry 'youngsModulus' is required"
expectError grid/nodes "(0 26 1)" "Entry 'nodes' is"
expectError grid/lower "(0.3 0 0)" "Entries 'lower' .* and 'upper'"
expectError grid/averagingSteps 0 "Entry 'averagingSteps' is 0"
expectError grid/beta 2 "Entry 'beta' is 2"
expectError grid/cloudInCellBelow -1 "Entry 'cloudInCellBelow' is -1"
expectError grid/negligibleWeight 0.1 "Entry 'negligibleWeight' is 0.1"
expectError grid/vectorised maybe "Entry 'vectorised' is 'maybe': allowed are true or false"
expectError grid/vectorised 2 "Entry 'vectorised' is '2': allowed are true or false"
expectError writeVtk 2 "Entry 'writeVtk' is '2': allowed are true or false"
expectError gather fast "Entry 'gather' is 'fast': allowed are"
expectError windowState compact "Entry 'windowState' is 'compact': allowed are"
expectError writeWindowValues 2 "Entry 'writeWindowValues' is '2': allowed are true or false"
expectError grid/radiusAverage median "Entry 'radiusAverage' is 'median': allowed are"
expectError collision "{ radiusAverage median; }" "Entry 'radiusAverage' is 'median': allowed are"
expectError fibers/maxSubSteps 0 "Entry 'maxSubSteps' is 0"
expectError fibers/drag stokes "Entry 'drag' is 'stokes': allowed are"
expectError fibers/holders cell "Entry 'holders' is 'cell': allowed are"
expectError grid/blocks even "Entry 'blocks' is 'even': allowed are"
expectError grid/balanceSteps 0 "Entry 'balanceSteps' is 0"
expectError grid/moveCost -1e-8 "Entry 'moveCost' is -1e-08"
expectError collision "{ sampling everywhere; }" "Entry 'sampling' is 'everywhere'"
expectError collision "{ depletion maybe; }" "Entry 'depletion' is 'maybe': allowed are true or false"
expectError collision "{ mode poisson; }" "Entry 'mode' is 'poisson': allowed are 2\\(expected discrete\\)"
expectError collision "{ mode discrete; seed -3; }" "Entry 'seed' is -3"
# The spread populations (docs/model.md sec. 12): read whether or not a fiber is weighted
expectError collision "{ spread { neighbours 0; } }" "Entry 'neighbours' is 0: allowed are finite values > 0"
expectError collision "{ spread { maxClustering -0.1; } }" "Entry 'maxClustering' is -0.1: allowed are finite values >= 0"
expectError collision "{ spread { maxSpacing -1; } }" "Entry 'maxSpacing' is -1: allowed are finite values >= 0"
expectError collision "{ spread { active perhaps; } }" "Entry 'active' is 'perhaps': allowed are true or false"
expectError air "{ rho -1.2; }" "Entry 'rho' is -1.2"
expectError air "{ mu noSuchField; }" "Entry 'mu' names field 'noSuchField', which does not exist"
# A field of the wrong kind is named as such
expectError air "{ U p; }" "Entry 'U' names field 'p', which is a volScalarField: U needs a volVectorField"
expectError air "{ rho U; }" "Entry 'rho' names field 'U', which is a volVectorField: 'rho' needs a volScalarField"
expectError fibers/fixed/across/points "((0.05 0.01 0.005))" "Entry 'points' has 1 points"
expectError fibers/fixed/across/hold glued "Entry 'hold' is 'glued'"
# Weighted fibers: the physical fibers a computed one stands for, or an injector's glass
# mass flow, and not both
expectError fibers/fixed/across/represents 0 "Entry 'represents' is 0: allowed are finite values > 0"
expectError fibers/injectors \
    "{ spinner { position (0.01 0.04 0.005); direction (1 0 0); velocity (0 0 0); length 0.01; rate 10; represents -3; } }" \
    "Entry 'represents' is -3: allowed are finite values > 0"
expectError fibers/injectors \
    "{ spinner { position (0.01 0.04 0.005); direction (1 0 0); velocity (0 0 0); length 0.01; rate 10; massFlowRate 0; } }" \
    "Entry 'massFlowRate' is 0: allowed are finite values > 0"
expectError fibers/injectors \
    "{ spinner { position (0.01 0.04 0.005); direction (1 0 0); velocity (0 0 0); length 0.01; rate 10; represents 4; massFlowRate 1e-3; } }" \
    "Injector 'spinner' has both 'represents' 4 and 'massFlowRate' 0.001: give one"
# The fibers' drag on the air: its switch and the one-way warning's level
expectError fibers/coupled maybe "Entry 'coupled' is 'maybe': allowed are true or false"
expectError fibers/couplingWarning 0 "Entry 'couplingWarning' is 0: allowed are finite values > 0"
# The fvOption that applies it (constant/fvOptions): a bad density, an unknown entry,
# two fields; listed without the function object's fields (coupled false): stops at
# its first step, saying how to get them
expectFvOptionError() {
    local entries="$1" pattern="$2" kind="$3"
    cp system/controlDict.good system/controlDict
    foamDictionary system/controlDict -entry endTime -set 0.004 > /dev/null
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }\n%s\n' \
        "fiberDrag { type fiberDragSource; libs (\"libdropletFiber.so\"); $entries }" > constant/fvOptions
    freshStart
    pimpleFoam > log.fvOption 2>&1
    local status=$?
    rm -f constant/fvOptions
    if [ "$status" -ne 0 ] && grep -q "FOAM FATAL $kind" log.fvOption \
        && grep -q -E -- "$pattern" log.fvOption; then
        checksPassed=$((checksPassed + 1))
        echo "ok: fvOption { $entries } -> $(grep -m1 -E -- "$pattern" log.fvOption)"
    else
        checksFailed=$((checksFailed + 1))
        echo "FAILED: fvOption { $entries } (exit $status); log:"
        grep -A4 "FOAM FATAL" log.fvOption || tail -5 log.fvOption
    fi
}
expectFvOptionError "rho -1.2;" "fvOption fiberDrag: entry 'rho' is -1.2: allowed are a density > 0" "IO ERROR"
expectFvOptionError "semiImplicitt true;" "Entry 'semiImplicitt' in dictionary '[^']*fiberDrag' is not known: did you mean 'semiImplicit'\\?" "IO ERROR"
expectFvOptionError "fields (U p);" "fvOption fiberDrag: entry 'fields' is 2\\(U p\\): allowed is one velocity field" "IO ERROR"
expectFvOptionError "" "the fields fiberDragForce and fiberDragCoeff are not there" "ERROR"

# The belt the fibers are laid on: its patch, cells, velocity in its plane, one way of
# giving it; a patch of two parallel faces (walls) is not a plane
expectError fibers/laydown "{ patch nowhere; cell 0.01; }" "Entry 'patch' names patch 'nowhere', which does not exist"
expectError fibers/laydown "{ patch walls; cell 0.01; }" "Entry 'patch' names patch 'walls', which is not planar"
expectError fibers/laydown "{ patch outlet; cell 0; }" "Entry 'cell' is 0: allowed are finite values > 0"
expectError fibers/laydown "{ patch outlet; cell 0.01; velocity (1 0 0); }" \
    "Entry 'velocity' is \\(1 0 0\\), which leaves the belt's plane"
expectError fibers/laydown "{ patch outlet; point (0.2 0 0); normal (1 0 0); width 0.05; cell 0.01; }" \
    "Entry 'laydown' needs the belt as 'patch', or as 'point', 'normal' and 'width', not both"
expectError fibers/laydown "{ patch outlet; width 0.05; cell 0.01; }" "Entry 'width' is for a belt given as point and normal"
expectError fibers/laydown "{ patch outlet; cel 0.01; }" "Entry 'cel' in dictionary '[^']*laydown' is not known: did you mean 'cell'\\?"
expectError fibers/laydown "{ patch outlet; cell 0.01; footprint middle; }" \
    "Entry 'footprint' is 'middle': allowed are 2\\(length centre\\)"
expectError fibers/laydown "{ patch outlet; cell 0.01; populations spreaded; }" \
    "Entry 'populations' is 'spreaded': allowed are 2\\(spread line\\)"
expectError fibers/laydown "{ patch outlet; cell 0.01; steadyFrom -1; }" \
    "Entry 'steadyFrom' is -1: allowed are finite values >= 0 \\[s\\]"

# A cloud named twice would be gathered twice (parcels, their mass and the
# captured mass doubled): stops, naming the entry, the cloud and what is allowed
expectError clouds "(kinematicCloud kinematicCloud)" \
    "Entry 'clouds' names cloud 'kinematicCloud' twice: allowed are the names of the run's clouds, each at most once"

# A misspelled or unknown entry, in every dictionary read: stops, naming the
# entry, its dictionary and the closest allowed entry (or all of them)
unknown() { echo "Entry '$1' in dictionary '[^']*$2' is not known: $3"; }
expectError grid/spacng 0.002 "$(unknown spacng grid "did you mean 'spacing'\\?")"
expectError collision "{ samplng integrated; }" "$(unknown samplng collision "did you mean 'sampling'\\?")"
expectError collision "{ spread { neighbors 4; } }" "$(unknown neighbors collision.spread "did you mean 'neighbours'\\?")"
expectError air "{ rhoo 1.2; }" "$(unknown rhoo air "did you mean 'rho'\\?")"
expectError air "{ temperature 300; }" "$(unknown temperature air "allowed are U, rho, mu\\.")"
expectError fibers/radus 1e-4 "$(unknown radus fibers "did you mean 'radius'\\?")"
expectError fibers/injectors \
    "{ spinner { position (0.01 0.04 0.005); direction (1 0 0); velocity (0 0 0); length 0.01; rat 10; } }" \
    "$(unknown rat injectors.spinner "did you mean 'rate'\\?")"
expectError fibers/fixed/across/hld pinned "$(unknown hld fixed.across "did you mean 'hold'\\?")"
expectError fiber "{ radius 1e-4; }" "$(unknown fiber dropletFiber "did you mean 'fibers'\\?")"
expectError writeVTK false "$(unknown writeVTK dropletFiber "did you mean 'writeVtk'\\?")"

# radiusAverage, a collision option, in both places: stops
cp system/controlDict.good system/controlDict.collisionMass
foamDictionary system/controlDict.collisionMass -entry "$fo/collision" -set "{ radiusAverage mass; }" > /dev/null
base=system/controlDict.collisionMass \
    expectError grid/radiusAverage mass "Entry 'radiusAverage' is given in both 'grid' and 'collision'"

# radiusAverage in its old place, grid: read, with a warning to move it
cp system/controlDict.good system/controlDict
foamDictionary system/controlDict -entry "$fo/grid/radiusAverage" -set number > /dev/null
foamDictionary system/controlDict -entry endTime -set 0.004 > /dev/null
freshStart
pimpleFoam > log.oldPlace 2>&1
status=$?
if [ $status -eq 0 ] \
    && grep -q "Entry 'radiusAverage' in 'grid' is read from its old place" log.oldPlace \
    && grep -q "radiusAverage number" log.oldPlace
then
    checksPassed=$((checksPassed + 1))
    echo "ok: grid/radiusAverage = number -> read (radiusAverage number), with a warning to move it"
else
    checksFailed=$((checksFailed + 1))
    echo "FAILED: grid/radiusAverage = number (exit $status): no warning, or not read; log:"
    grep -B2 -A4 "radiusAverage" log.oldPlace | head -20
fi

# A grid box that misses the fiber (at x = 0.05): the run goes on, warned
# once that its 6 segments' collision samples lie outside the grid
cp system/controlDict.good system/controlDict
foamDictionary system/controlDict -entry "$fo/grid/lower" -set "(0.06 0 0)" > /dev/null
foamDictionary system/controlDict -entry endTime -set 0.006 > /dev/null
freshStart
pimpleFoam > log.outside 2>&1
status=$?
if [ $status -eq 0 ] \
    && grep -q "dropletFiber: 6 collision sample points of fiber segments lie outside the grid box at time 0.002" log.outside \
    && grep -q "Enlarge grid lower (0.06 0 0)" log.outside \
    && [ "$(grep -c "lie outside the grid box" log.outside)" -eq 1 ]
then
    checksPassed=$((checksPassed + 1))
    echo "ok: grid/lower = (0.06 0 0) -> warned once: $(grep -m1 "lie outside the grid box" log.outside)"
else
    checksFailed=$((checksFailed + 1))
    echo "FAILED: grid/lower = (0.06 0 0) (exit $status): no single warning about samples outside the grid; log:"
    grep -A3 "outside the grid" log.outside | head -10
fi

# A misspelled entry in an edit of the dictionary during the run (read
# again, runTimeModifiable) stops the run too: collision carries no state, so
# only the check of the keys can stop it. The edit is made by OpenFOAM's
# timeActivatedFileUpdate at time 0.01, so it does not race the run.
cp system/controlDict.good system/controlDict
foamDictionary system/controlDict -entry runTimeModifiable -set true > /dev/null
foamDictionary system/controlDict -entry endTime -set 0.02 > /dev/null
foamDictionary system/controlDict -entry OptimisationSwitches \
    -add "{ fileModificationSkew 0; fileModificationChecking timeStamp; }" > /dev/null
foamDictionary system/controlDict -entry functions/editControlDict \
    -add "{ type timeActivatedFileUpdate; libs (\"libutilityFunctionObjects.so\"); fileToUpdate \"\$FOAM_CASE/system/controlDict\"; timeVsFile ((0.01 \"\$FOAM_CASE/system/controlDict.typo\")); }" > /dev/null
cp system/controlDict system/controlDict.start

# expectStopAtEdit COLLISION PATTERN LOG: the run from controlDict.start, whose
# dictionary the edit at time 0.01 sets collision to COLLISION, stops there
# (before time 0.02) with a FatalIOError saying PATTERN
expectStopAtEdit() {
    local collision="$1" pattern="$2" log="$3"
    cp system/controlDict.start system/controlDict
    foamDictionary system/controlDict -entry "$fo/collision" -set "$collision" > /dev/null
    cp system/controlDict system/controlDict.typo
    cp system/controlDict.start system/controlDict
    touch -d "1 hour ago" system/controlDict
    freshStart
    pimpleFoam > "$log" 2>&1
    local status=$?
    check "grep -q '^Time = 0.01$' $log && ! grep -q '^Time = 0.02$' $log" \
        "collision = $collision edited during the run: not stopped at the edit"
    expectFatalIOError "$status" "$log" "$pattern" "collision = $collision edited during the run"
}
expectStopAtEdit "{ samplng integrated; }" \
    "$(unknown samplng collision "did you mean 'sampling'\\?")" log.runTimeTypo

# collision.depletion is read at the start only (the table's columns follow it):
# the same edit at time 0.01, to 'depletion false', stops the run naming it
expectStopAtEdit "{ depletion false; }" \
    "Entry 'collision.depletion' was edited during the run \(true -> false\)" log.runTimeDepletion

# fibers.laydown is read at the start only (the mat laid so far is on the belt in
# force): its cell edited at time 0.01 stops the run there, naming it
cp system/controlDict.start system/controlDict
foamDictionary system/controlDict -entry "$fo/fibers/laydown" -set "{ patch outlet; cell 0.002; }" > /dev/null
cp system/controlDict system/controlDict.laydownStart
foamDictionary system/controlDict -entry "$fo/fibers/laydown/cell" -set 0.004 > /dev/null
cp system/controlDict system/controlDict.typo
cp system/controlDict.laydownStart system/controlDict
touch -d "1 hour ago" system/controlDict
freshStart
pimpleFoam > log.runTimeLaydown 2>&1
status=$?
check "grep -q '^Time = 0.01$' log.runTimeLaydown && ! grep -q '^Time = 0.02$' log.runTimeLaydown" \
    "fibers.laydown edited during the run: not stopped at the edit"
expectFatalIOError "$status" log.runTimeLaydown "Entry 'fibers.laydown' was edited during the run" \
    "fibers.laydown edited during the run"

cp system/controlDict.good system/controlDict
checkSummary
