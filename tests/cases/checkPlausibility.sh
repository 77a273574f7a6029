#!/usr/bin/env bash
# Unit slips run with a FOAM Warning naming the entry, the value, the plausible range
# and the likely slip: a fiber radius of 3 (micrometres meant), a density of 2.5 (g/cm3),
# Young's modulus 7e4 (GPa meant as MPa...), a fixed fiber's own radius, a droplet
# density of 1, an air density of 5000, a grid spacing 1/125 of the mesh's cells; the
# good case warns of none. Usage: checkPlausibility.sh CASE_DIR WORK_DIR (fixedFiber:
# 5 mm cells)
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
prepareCaseCopy "$1" "$2"
fo=functions/dropletFiber
foamDictionary system/controlDict -entry endTime -set 0.004 > /dev/null
pimpleFoam > log.good 2>&1
check "[ $? -eq 0 ] && ! grep -q 'plausible are' log.good" "the good case: failed, or warned of a plausible value"

rm -rf 0.0*
set() { foamDictionary "$1" -entry "$2" -set "$3" > /dev/null || echo "FAILED: cannot set $2"; }
set system/controlDict $fo/fibers/radius 3
set system/controlDict $fo/fibers/density 2.5
set system/controlDict $fo/fibers/youngsModulus 7e4
foamDictionary system/controlDict -entry $fo/fibers/fixed/across/radius -add 2e-8 > /dev/null
foamDictionary system/controlDict -entry $fo/air -add "{ rho 5000; }" > /dev/null
# a weight of 1e30, and a spinner's 800 kg/h given as kg/s
foamDictionary system/controlDict -entry $fo/fibers/fixed/across/represents -add 1e30 > /dev/null
foamDictionary system/controlDict -entry $fo/fibers/injectors -add \
    "{ spinner { position (0.02 0.01 0.005); direction (0 1 0); velocity (0.1 0 0); length 0.002; rate 250; massFlowRate 800; radius 4e-6; density 2500; youngsModulus 7e10; } }" \
    > /dev/null
set system/controlDict $fo/grid "{ lower (0.05 0.02 0); upper (0.051 0.021 0.01); spacing 4e-5; }"
# the streams' droplet density (their injection table), 1 instead of 1000
sed -i 's/ 1000 1$/ 1 1/' constant/parcelInjectionProperties
pimpleFoam > log.slips 2>&1
status=$?
check "[ $status -eq 0 ] && tail -n 3 log.slips | grep -q '^End'" "the run with slips: exit $status, did not end"
expectWarning() {
    check "grep -q -F \"$1\" log.slips" "no warning: $1"
}
expectWarning "Entry 'radius' is 3 m: plausible are 1e-07 to 0.001 m; a radius in micrometres or millimetres given in metres? (3 um is 3e-6 m)"
expectWarning "Entry 'density' is 2.5 kg/m3: plausible are 100 to 25000 kg/m3; a density in g/cm3 given in kg/m3? (2.5 g/cm3 is 2500 kg/m3)"
expectWarning "Entry 'youngsModulus' is 70000 Pa: plausible are 100000 to 1e+12 Pa; a modulus in MPa or GPa given in Pa? (70 GPa is 7e10 Pa)"
expectWarning "Entry 'radius' is 2e-08 m: plausible are 1e-07 to 0.001 m (the run goes on with it)"
expectWarning "Entry 'represents' is 1e+30 fibers: plausible are 1 to 1e+12 fibers; a glass flow or a count per second given as the fibers one computed fiber stands for?"
expectWarning "Entry 'massFlowRate' is 800 kg/s: plausible are 1e-06 to 1 kg/s; a spinner's kg/h given in kg/s? (a spinner's glass flow is a few hundred kg/h: 300 kg/h is 0.083 kg/s)"
expectWarning "Entry 'rho' is 5000 kg/m3: plausible are 0.01 to 2000 kg/m3; a density in g/m3 or g/l given in kg/m3?"
expectWarning "Entry 'spacing' gives a node spacing of 4e-05 m, 0.008 times the mesh's mean cell size 0.005 m: plausible are 0.01 to 100 times it"
expectWarning "the droplet density (the parcels' rho: the clouds' constantProperties rho0 or their injection data) is 1 kg/m3: plausible are 100 to 25000 kg/m3; a density in g/cm3 given in kg/m3?"
check "grep -B4 -F \"Entry 'radius' is 3 m\" log.slips | grep -q 'FOAM Warning'" "the radius's message is not a FOAM Warning"
check "grep -B1 -F \"Entry 'radius' is 2e-08 m\" log.slips | grep -q 'fibers.fixed.across'" "the fixed fiber's warning does not name its dictionary"
checkSummary
