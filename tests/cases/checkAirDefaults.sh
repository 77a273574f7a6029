#!/usr/bin/env bash
# The air's density and viscosity, when not given, are what the solver reads: rhoInf
# of transportProperties for icoUncoupledKinematicParcelFoam (fiberStream without its
# air entries), rho for pimpleFoam's cases (fixedFiber), the fields rho and thermo:mu
# for a compressible solver (uncoupledKinematicParcelFoam); a transportProperties
# without a density stops naming the entries looked for. Usage: checkAirDefaults.sh
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
# A compressible solver (uncoupledKinematicParcelFoam: fixedFiber with a perfect-gas
# thermophysical model and its own cloud): the fields rho and thermo:mu
prepareCaseCopy "$fixedFiber" "$work/thermo"
foamDictionary system/controlDict -entry functions/kinematicCloud -remove > /dev/null
foamDictionary system/controlDict -entry application -set uncoupledKinematicParcelFoam > /dev/null
foamDictionary system/controlDict -entry endTime -set 0.004 > /dev/null
foamDictionary constant/kinematicCloudProperties -entry solution/interpolationSchemes/thermo:mu \
    -add cell > /dev/null
cat > constant/thermophysicalProperties <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object thermophysicalProperties; }
thermoType
{
    type hePsiThermo; mixture pureMixture; transport const; thermo hConst;
    equationOfState perfectGas; specie specie; energy sensibleEnthalpy;
}
mixture
{
    specie { molWeight 28.9; }
    thermodynamics { Cp 1005; Hf 0; }
    transport { mu 1.8e-05; Pr 0.7; }
}
DICT
# p and T: p's boundary types with a pressure of 1 bar and 300 K
sed -e 's/\[0 2 -2 0 0 0 0\]/[1 -1 -2 0 0 0 0]/' -e 's/uniform 0;/uniform 100000;/g' 0/p > 0/p.new
mv 0/p.new 0/p
sed -e 's/object *p;/object T;/' -e 's/\[1 -1 -2 0 0 0 0\]/[0 0 0 1 0 0 0]/' \
    -e 's/uniform 100000;/uniform 300;/g' 0/p > 0/T
uncoupledKinematicParcelFoam > log.run 2>&1
check "[ $? -eq 0 ]" "uncoupledKinematicParcelFoam failed: $(grep -A3 'FOAM FATAL' log.run | head -4)"
check "grep -q \"air: U field U, rho field rho (the solver's thermophysical model), mu field thermo:mu (the solver's thermophysical model)\" log.run" \
    "uncoupledKinematicParcelFoam: the air is not the fields rho and thermo:mu: $(grep 'air: U field' log.run)"
checkSummary
