#!/usr/bin/env bash
# Restart with another number of processors than the run that wrote the state:
#  - a serial run's state, decomposed onto the case's ranks (decomposePar
#    copies uniform/ into every processor directory): every processor keeps the fibers whose first point
#    lies in its cells, and the run continues as the serial one does (1e-8);
#  - a parallel run's state (on the ranks of the case's decomposeParDict),
#    reconstructed: reconstructPar copies processor 0's uniform/, which holds
#    only processor 0's fibers, and the serial restart stops with a
#    FatalIOError saying on how many processors the state was written and
#    naming reconstructDropletFiberState; that merges the processors' states:
#    the merged window equals the serial run's at T/2 and its fibers and
#    totals too (1e-8), and the run continues serially and, decomposed anew,
#    on 2 ranks as the serial one does (fibers and totals at T, 1e-8).
# Usage: checkRestartProcessors.sh CASE_DIR WORK_DIR T_HALF T
set -uo pipefail
caseDir="$1"; work="$2"; half="$3"; end="$4"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
state=uniform/dropletFiber/dropletFiber

# Serial 0 -> T, and serial 0 -> T/2 continued on the case's ranks
prepareCaseCopy "$caseDir" "$work/serial"
ranks="$(foamDictionary -entry numberOfSubdomains -value system/decomposeParDict)"
app="$(foamDictionary -entry application -value system/controlDict)"
./Allrun > /dev/null 2>&1 || { echo "FAILED: serial run"; exit 1; }
prepareCaseCopy "$caseDir" "$work/serialThenParallel"
sed -i "s/^endTime .*/endTime         $half;/" system/controlDict
./Allrun > /dev/null 2>&1 || { echo "FAILED: serial run to $half"; exit 1; }
sed -i "s/^endTime .*/endTime         $end;/" system/controlDict
rm -rf processor*
decomposePar -time "$half" > log.decomposeHalf 2>&1 || { echo "FAILED: decomposePar"; exit 1; }
mpirun -np "$ranks" "$app" -parallel > log.restart 2>&1
status=$?
check "[ $status -eq 0 ] && grep -q 'restarted from' log.restart" \
    "serial state on $ranks ranks: exit $status or the state was not read"
check "'$PY' '$here/compareFiberUnion.py' '$work/serial/$end/$state' . '$end/$state' 1e-8" \
    "serial state on $ranks ranks: the fibers differ from the serial run's"

# The case's ranks 0 -> T/2, reconstructed, continued serially: stops, naming
# the count and the utility
prepareCaseCopy "$caseDir" "$work/parallelThenSerial"
sed -i "s/^endTime .*/endTime         $half;/" system/controlDict
./Allrun -parallel > /dev/null 2>&1 || { echo "FAILED: parallel run to $half"; exit 1; }
reconstructPar -time "$half" > log.reconstructPar 2>&1 || { echo "FAILED: reconstructPar"; exit 1; }
sed -i "s/^endTime .*/endTime         $end;/" system/controlDict
"$app" > log.restart 2>&1
status=$?
check "[ $status -ne 0 ] && grep -q 'FOAM FATAL IO ERROR' log.restart" \
    "parallel state restarted serially: exit $status, expected a FatalIOError"
check "grep -q 'was written by processor 0 of a run on $ranks processors' log.restart && grep -q 'Restart on $ranks processors' log.restart" \
    "parallel state restarted serially: the message does not name the processor count"
check "grep -q 'run reconstructPar and reconstructDropletFiberState, then' log.restart" \
    "parallel state restarted serially: the message does not name reconstructDropletFiberState"
grep -A4 "FOAM FATAL IO ERROR" log.restart | head -6

# The processors' states merged: the serial run's window, fibers and totals at T/2
reconstructDropletFiberState -time "$half" > log.reconstructDropletFiberState 2>&1
status=$?
check "[ $status -eq 0 ] && grep -q 'merged the restart states of $ranks processors' log.reconstructDropletFiberState" \
    "reconstructDropletFiberState: exit $status or no merge reported"
check "! grep -q -E '^ *(processors?|gridBlock|gridPartition) ' '$half/$state'" \
    "the merged state keeps a parallel run's entries"
check "'$PY' '$here/compareBlockWindows.py' '$work/serial/$half/$state' . '$half/$state' 1e-8 --merged" \
    "the merged window differs from the serial run's at $half"
check "'$PY' '$here/compareState.py' '$work/serial/$half/$state' '$half/$state' 1e-8 --only fibers,injectors,totals > log.compareHalf" \
    "the merged fibers or totals differ from the serial run's at $half"

# ... continued serially, and decomposed anew onto 2 ranks (split across the
# stream, not along it as the case's): the serial run at T
rm -rf ../mergedOnTwo; cp -r . ../mergedOnTwo
rm -rf processor*
"$app" > log.restart 2>&1
status=$?
check "[ $status -eq 0 ] && grep -q 'restarted from' log.restart" \
    "merged state continued serially: exit $status or the state was not read"
check "'$PY' '$here/compareState.py' '$work/serial/$end/$state' '$end/$state' 1e-8 --only fibers,injectors,totals > log.compareEnd" \
    "merged state continued serially: the fibers or totals differ from the serial run's"
cd ../mergedOnTwo || exit 1
rm -rf processor*
foamDictionary system/decomposeParDict -entry numberOfSubdomains -set 2 > /dev/null
foamDictionary system/decomposeParDict -entry method -set simple > /dev/null
foamDictionary system/decomposeParDict -entry coeffs/n -set '(1 2 1)' > /dev/null
decomposePar -time "$half" > log.decomposeHalf 2>&1 || { echo "FAILED: decomposePar onto 2"; exit 1; }
mpirun -np 2 "$app" -parallel > log.restart 2>&1
status=$?
check "[ $status -eq 0 ] && grep -q 'restarted from' log.restart" \
    "merged state on 2 ranks: exit $status or the state was not read"
check "'$PY' '$here/compareFiberUnion.py' '$work/serial/$end/$state' . '$end/$state' 1e-8 > log.compareEnd" \
    "merged state on 2 ranks: the fibers or totals differ from the serial run's"
checkSummary
