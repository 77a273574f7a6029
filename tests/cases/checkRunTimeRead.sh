#!/usr/bin/env bash
# A run whose controlDict is edited while it runs (runTimeModifiable): an
# entry without state (writeGridVtk) is applied from then on, an entry that
# carries the run's state (the grid spacing) stops the run with an error that
# names it, the running and the edited value. The edits are made by OpenFOAM's
# timeActivatedFileUpdate at set simulation times, so they do not race the run.
# Usage: checkRunTimeRead.sh CASE_DIR WORK_DIR
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
prepareCaseCopy "$1" "$2"

fo=functions/dropletFiber
set_() { foamDictionary system/controlDict -entry "$1" -set "$2" > /dev/null; }
add_() { foamDictionary system/controlDict -entry "$1" -add "$2" > /dev/null; }
set_ runTimeModifiable true
# Every edit is seen at the next step (the default skew would wait 10 s)
add_ OptimisationSwitches "{ fileModificationSkew 0; fileModificationChecking timeStamp; }"
add_ "$fo/grid" "{ spacing 0.002; }"
add_ "$fo/writeGridVtk" true
add_ functions/editControlDict "{ type timeActivatedFileUpdate; libs (\"libutilityFunctionObjects.so\"); fileToUpdate \"\$FOAM_CASE/system/controlDict\"; timeVsFile ((0.02 \"\$FOAM_CASE/system/controlDict.gridVtkOff\") (0.06 \"\$FOAM_CASE/system/controlDict.newSpacing\")); }"
cp system/controlDict system/controlDict.start
set_ "$fo/writeGridVtk" false
cp system/controlDict system/controlDict.gridVtkOff
set_ "$fo/grid/spacing" 0.001
cp system/controlDict system/controlDict.newSpacing
cp system/controlDict.start system/controlDict
touch -d "1 hour ago" system/controlDict

pimpleFoam > log.runTimeRead 2>&1
status=$?
vtk=postProcessing/dropletFiber/0
check "[ $status -ne 0 ]" "pimpleFoam exited with $status, expected the edited spacing to stop it"
check 'grep -q "^Time = 0.06$" log.runTimeRead' "the run stopped before the spacing was edited"
check '! grep -q "^Time = 0.066$" log.runTimeRead' "the run went on after the spacing was edited"
# Applied: the re-read is reported, and no grid files after it (fibers' still)
check 'grep -q "settings re-read at time 0.02" log.runTimeRead' "no re-read reported at 0.02"
check 'grep -q "writeGridVtk false" log.runTimeRead' "the re-read settings do not show writeGridVtk false"
check "[ -f $vtk/grid_0.01.vti ] && [ -f $vtk/grid_0.018.vti ]" "no grid VTK files before the edit"
check "[ ! -f $vtk/grid_0.03.vti ] && [ ! -f $vtk/grid_0.05.vti ]" "grid VTK files written after writeGridVtk was set false"
check "[ -f $vtk/fibers_0.05.vtp ]" "the fiber VTK files stopped too"
# Stopped: the error names the entry, both values and that it needs a new run
check 'grep -q "FOAM FATAL IO ERROR" log.runTimeRead' "no FatalIOError in the log"
check 'grep -q "Entry .spacing. was edited during the run: the run uses nodes (101 26 1), the dictionary now says nodes (201 51 1)" log.runTimeRead' \
    "the error does not name the entry with its running and edited values"
check 'grep -q "takes effect only in a new run" log.runTimeRead' "the error does not say it takes effect in a new run"
grep -A4 "FOAM FATAL IO ERROR" log.runTimeRead | head -6
checkSummary
