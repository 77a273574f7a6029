#!/usr/bin/env bash
# Bad entries of fibers.turbulence stop the run with a FatalIOError naming the
# entry, the value and what is allowed; ornsteinUhlenbeck in a laminar case
# stops saying it needs a RAS or LES model; the laminar case's log says the
# turbulent air is off by default and why.
# Usage: checkTurbulenceEntries.sh RAS_CASE_DIR LAMINAR_CASE_DIR WORK_DIR
set -uo pipefail
rasCase="$(cd "$1" && pwd)"; laminarCase="$(cd "$2" && pwd)"; work="$3"
mkdir -p "$work"; work="$(cd "$work" && pwd)"
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
fo=functions/dropletFiber/fibers/turbulence

# expectError CASE_COPY VALUE PATTERN: fibers.turbulence set to VALUE, a few
# steps run, PATTERN expected in the FatalIOError
expectError() {
    local copy="$1" value="$2" pattern="$3"
    cd "$copy" || exit 1
    cp system/controlDict.good system/controlDict
    foamDictionary system/controlDict -entry "$fo" -add "$value" > /dev/null
    icoUncoupledKinematicParcelFoam > log.bad 2>&1
    expectFatalIOError $? log.bad "$pattern" "turbulence $value"
}

for which in ras laminar; do
    source="$rasCase"; [ "$which" = laminar ] && source="$laminarCase"
    prepareCaseCopy "$source" "$work/$which"
    sed -i "s/^endTime .*/endTime         0.004;/" system/controlDict
    cp system/controlDict system/controlDict.good
done

expectError "$work/ras" "{ model random; }" "Entry 'model' is 'random': allowed are 2\(none ornsteinUhlenbeck\)"
expectError "$work/ras" "{ timeScaleCoeff -0.5; }" "Entry 'timeScaleCoeff' is -0.5: allowed are finite values > 0"
expectError "$work/ras" "{ lengthScaleCoeff 0; }" "Entry 'lengthScaleCoeff' is 0: allowed are finite values > 0"
expectError "$work/ras" "{ seed -3; }" "Entry 'seed' is -3: allowed are integers from 0 to"
expectError "$work/ras" "{ timeScale 0.3; }" "Entry 'timeScale' in dictionary '[^']*turbulence' is not known: did you mean 'timeScaleCoeff'\?"
expectError "$work/laminar" "{ model ornsteinUhlenbeck; }" \
    "Entry 'model' is 'ornsteinUhlenbeck' but the case's turbulence model is 'laminar'"

# The laminar case, without the entry: off, saying why
cd "$work/laminar" || exit 1
cp system/controlDict.good system/controlDict
icoUncoupledKinematicParcelFoam > log.good 2>&1
check "grep -q \"fibers.turbulence: none (default with the case's turbulence model 'laminar')\" log.good" \
    "the laminar run's log does not say the turbulent air is off by default"
checkSummary
