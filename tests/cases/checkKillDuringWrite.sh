#!/usr/bin/env bash
# A run killed during a write, then restarted from that time: an exact
# continuation, or an error naming the missing file, never a silent fresh
# start. OpenFOAM writes the fields of a time before it executes the function
# objects, so a kill can leave a time directory in any of these states; each
# is made deterministically from a finished run (as a kill would leave it),
# then one real `kill -9` at a write time. As in checkRestart.sh, the killed
# runs end at the write time 0.1 and are restarted to 0.2; the state at 0.2 is
# compared with the continuous run 0 -> 0.2 to 1e-10 (the averaging window
# differs in the last bits, as in checkRestart.sh, whose cmp does not fail).
# Usage: checkKillDuringWrite.sh CASE_DIR WORK_DIR (fiberStream: writes every 0.05 s)
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
here="$(cd "${0%/*}" && pwd)"
work="$2"
prepareCaseCopy "$1" "$work/full"
app="$(foamDictionary -entry application -value system/controlDict)"
"$app" > "log.$app" 2>&1 || { tail -20 "log.$app"; echo "FAILED: the continuous run"; exit 1; }
state=uniform/dropletFiber/dropletFiber
full="$work/full"
setEndTime() { sed -i "s/^endTime .*/endTime         $1;/" system/controlDict; }

# The run to 0.1, the starting point of the simulated kills
rm -rf "${work:?}/half"; cp -r "$full" "$work/half"; cd "$work/half" || exit 1
rm -rf 0.05 0.1 0.15 0.2 postProcessing log.*
setEndTime 0.1
"$app" > "log.$app" 2>&1 || { tail -20 "log.$app"; echo "FAILED: the run to 0.1"; exit 1; }
setEndTime 0.2

# killedCopy NAME: a copy of the run to 0.1, to be restarted to 0.2
killedCopy() {
    rm -rf "${work:?}/$1"; cp -r "$work/half" "$work/$1"
    cd "$work/$1" || exit 1
}

# restartEndsExactly NAME: the restart ran to its end and continued the run
restartEndsExactly() {
    check 'tail -n 3 log.restart | grep -q "^End"' "$1: the restart did not end"
    check 'grep -q "restarted from .*0.1/$state" log.restart' "$1: the restart did not read the state"
    check '"$PY" "$here/compareState.py" "$full/0.2/$state" "0.2/$state" 1e-10 > /dev/null' \
        "$1: the state at 0.2 differs from the continuous run"
    check '"$PY" "$here/compareWindow.py" "$full/0.2/$state.gridWindow" "0.2/$state.gridWindow" 1e-10' \
        "$1: the averaging window at 0.2 differs from the continuous run"
    check '"$PY" "$here/compareWindow.py" "$full/0.2/$state.gridWindowValues" "0.2/$state.gridWindowValues" 1e-10' \
        "$1: the averaging window's node values at 0.2 differ from the continuous run"
}

# restartStopsNaming NAME FILE: the restart stopped with an error naming FILE
restartStopsNaming() {
    check "! tail -n 3 log.restart | grep -q '^End'" "$1: the restart ran on"
    check 'grep -q "FOAM FATAL IO ERROR" log.restart' "$1: no FatalIOError"
    check "grep -q -E 'Restart state .*$2\"? is missing' log.restart" "$1: the error does not name $2"
    check '! grep -q "starting fresh" log.restart' "$1: started fresh"
    echo "$1: $(grep -m1 "Restart state" log.restart)"
}

# 1. After the fields, before the state (the marker, written with the fields,
#    says that the state should follow)
killedCopy fieldsOnly
rm -f 0.1/$state 0.1/$state.gridWindow
"$app" > log.restart 2>&1
restartStopsNaming fieldsOnly "0.1/$state"

# 2. During the state's write: the window complete, the dictionary's temporary
#    half written
killedCopy windowOnly
head -c 300 0.1/$state > 0.1/$state.tmp; rm -f 0.1/$state
"$app" > log.restart 2>&1
restartStopsNaming windowOnly "0.1/$state"

# 3. During the window's write: its temporary half written
killedCopy windowHalf
head -c 3000 0.1/$state.gridWindow > 0.1/$state.gridWindow.tmp
rm -f 0.1/$state 0.1/$state.gridWindow
"$app" > log.restart 2>&1
restartStopsNaming windowHalf "0.1/$state"

# 4. After the state, before OpenFOAM's functionObjectProperties: continues
killedCopy stateWritten
rm -f 0.1/uniform/functionObjects/functionObjectProperties
"$app" > log.restart 2>&1
restartEndsExactly stateWritten

# 5. The state lost, the user asks for a fresh start: runs on, saying so
killedCopy fresh
rm -f 0.1/$state 0.1/$state.gridWindow
foamDictionary system/controlDict -entry functions/dropletFiber/restart -add fresh > /dev/null
"$app" > log.restart 2>&1
check 'tail -n 3 log.restart | grep -q "^End"' "fresh: the restart did not end"
check 'grep -q "restart fresh: starting from the dictionary" log.restart' "fresh: not said"

# 6. A real kill -9 at the write of 0.1, as soon as the fields are there
rm -rf "${work:?}/killed"; cp -r "$full" "$work/killed"; cd "$work/killed" || exit 1
rm -rf 0.05 0.1 0.15 0.2 postProcessing log.*
setEndTime 0.1
"$app" > log.killed 2>&1 &
pid=$!
for _ in $(seq 1 6000); do
    [ -f 0.1/$state.marker ] && break
    kill -0 $pid 2> /dev/null || break
    sleep 0.01
done
kill -9 $pid 2> /dev/null; wait $pid 2> /dev/null
check '[ -d 0.1 ]' "kill: the run ended before writing 0.1"
echo "kill -9 left in 0.1/uniform/dropletFiber: $(ls 0.1/uniform/dropletFiber 2> /dev/null | tr '\n' ' ')"
setEndTime 0.2
"$app" > log.restart 2>&1
if [ -f 0.1/$state ]; then
    restartEndsExactly kill
else
    restartStopsNaming kill "0.1/$state"
fi
checkSummary
