#!/usr/bin/env bash
# The air's density and viscosity, when not given, are what the solver reads: rhoInf
# of transportProperties for icoUncoupledKinematicParcelFoam (fiberStream without its
# air entries), rho for pimpleFoam's cases (fixedFiber); a transportProperties without
# a density stops naming the entries looked for. Usage: checkAirDefaults.sh
# FIBERSTREAM_DIR FIXEDFIBER_DIR WORK_DIR
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
work="$3"
fiberStream="$(cd "$1" && pwd)"; fixedFiber="$(cd "$2" && pwd)"

prepareCaseCopy "$fiberStream" "$work/rhoInf"
foamDictionary system/controlDict -entry functions/dropletFiber/air -remove > /dev/null
foamDictionary system/controlDict -entry endTime -set 0.01 > /dev/null
icoUncoupledKinematicParcelFoam > log.run 2>&1
check "[ $? -eq 0 ]" "icoUncoupledKinematicParcelFoam without air entries failed: $(grep -A3 'FOAM FATAL' log.run | head -4)"
check "grep -q 'air: U field U, rho 1.2 (transportProperties rhoInf), mu 1.8e-05 (transportProperties rhoInf \* nu)' log.run" \
    "icoUncoupledKinematicParcelFoam: the air is not rhoInf and rhoInf * nu: $(grep 'air: U field' log.run)"

prepareCaseCopy "$fixedFiber" "$work/rho"
foamDictionary system/controlDict -entry endTime -set 0.004 > /dev/null
pimpleFoam > log.run 2>&1
check "[ $? -eq 0 ]" "pimpleFoam failed"
check "grep -q 'air: U field U, rho 1.2 (transportProperties rho), mu 1.8e-05 (transportProperties rho \* nu)' log.run" \
    "pimpleFoam: the air is not rho and rho * nu: $(grep 'air: U field' log.run)"

foamDictionary constant/transportProperties -entry rho -remove > /dev/null
rm -rf 0.0*
pimpleFoam > log.noDensity 2>&1
status=$?
check "[ $status -ne 0 ] && grep -q 'FOAM FATAL IO ERROR' log.noDensity" "no density: exit $status, no FatalIOError"
check "grep -q \"Entry 'rho' is transportProperties (the default), but constant/transportProperties has no density entry of 2(rho rhoInf)\" log.noDensity" \
    "no density: the error does not name the entries looked for: $(grep -A1 'FOAM FATAL IO' log.noDensity | tail -1)"
checkSummary
