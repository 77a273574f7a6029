#!/usr/bin/env bash
# Restart with another number of processors than the run that wrote the state:
#  - a serial run's state, decomposed (decomposePar copies uniform/ into every
#    processor directory): every processor keeps the fibers whose first point
#    lies in its cells, and the run continues as the serial one does (1e-8);
#  - a parallel run's state, reconstructed (reconstructPar copies processor 0's
#    uniform/, which holds only processor 0's fibers): the serial restart stops
#    with a FatalIOError saying on how many processors the state was written.
# Usage: checkRestartProcessors.sh CASE_DIR WORK_DIR T_HALF T
set -uo pipefail
caseDir="$1"; work="$2"; half="$3"; end="$4"
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
state=uniform/dropletFiber/dropletFiber

# Serial 0 -> T, and serial 0 -> T/2 continued on 2 ranks
prepareCaseCopy "$caseDir" "$work/serial"
app="$(foamDictionary -entry application -value system/controlDict)"
./Allrun > /dev/null 2>&1 || { echo "FAILED: serial run"; exit 1; }
prepareCaseCopy "$caseDir" "$work/serialThenParallel"
sed -i "s/^endTime .*/endTime         $half;/" system/controlDict
./Allrun > /dev/null 2>&1 || { echo "FAILED: serial run to $half"; exit 1; }
sed -i "s/^endTime .*/endTime         $end;/" system/controlDict
rm -rf processor*
decomposePar -time "$half" > log.decomposeHalf 2>&1 || { echo "FAILED: decomposePar"; exit 1; }
mpirun -np 2 "$app" -parallel > log.restart 2>&1
status=$?
check "[ $status -eq 0 ] && grep -q 'restarted from' log.restart" \
    "serial state on 2 ranks: exit $status or the state was not read"
check "'$PY' '$here/compareFiberUnion.py' '$work/serial/$end/$state' . '$end/$state' 1e-8" \
    "serial state on 2 ranks: the fibers differ from the serial run's"

# 2 ranks 0 -> T/2, reconstructed, continued serially: stops, naming the count
prepareCaseCopy "$caseDir" "$work/parallelThenSerial"
sed -i "s/^endTime .*/endTime         $half;/" system/controlDict
./Allrun -parallel > /dev/null 2>&1 || { echo "FAILED: parallel run to $half"; exit 1; }
reconstructPar -time "$half" > log.reconstructPar 2>&1 || { echo "FAILED: reconstructPar"; exit 1; }
sed -i "s/^endTime .*/endTime         $end;/" system/controlDict
"$app" > log.restart 2>&1
status=$?
check "[ $status -ne 0 ] && grep -q 'FOAM FATAL IO ERROR' log.restart" \
    "parallel state restarted serially: exit $status, expected a FatalIOError"
check "grep -q 'was written by processor 0 of a run on 2 processors' log.restart && grep -q 'Restart on 2 processors' log.restart" \
    "parallel state restarted serially: the message does not name the processor count"
grep -A4 "FOAM FATAL IO ERROR" log.restart | head -6
checkSummary
