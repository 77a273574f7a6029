#!/usr/bin/env bash
# The per-step table is written with writePrecision 10 (in OpenFOAM's
# scientific notation: 10 digits after the decimal point) unless the function
# object's own writePrecision says otherwise, whatever the case's
# writePrecision. Usage: checkTablePrecision.sh CASE_DIR WORK_DIR
set -uo pipefail
# shellcheck disable=SC1091
. "$(cd "${0%/*}" && pwd)/lib/prepareCase.sh"
prepareCaseCopy "$1" "$2"
fo=functions/dropletFiber
table=postProcessing/dropletFiber/0/dropletFiber.dat

# Most digits after the decimal point of any number in the table after its
# time column (2.3561944902e-06: 10)
mostDigits() {
    python3 - "$table" <<'PYTHON'
import re, sys
most = 0
for line in open(sys.argv[1]):
    if line.startswith("#"):
        continue
    for field in line.split()[1:]:
        mantissa = re.split("[eE]", field)[0]
        most = max(most, len(mantissa.partition(".")[2]))
print(most)
PYTHON
}

# runWith FO_PRECISION: the case's writePrecision 6, the function object's
# FO_PRECISION (none: no entry); run a few steps
runWith() {
    foamListTimes -rm > /dev/null 2>&1; rm -rf postProcessing
    cp system/controlDict.orig system/controlDict
    foamDictionary system/controlDict -entry writePrecision -set 6 > /dev/null
    foamDictionary system/controlDict -entry endTime -set 0.01 > /dev/null
    if [ "$1" = none ]; then
        foamDictionary system/controlDict -entry "$fo/writePrecision" -remove > /dev/null
    else
        foamDictionary system/controlDict -entry "$fo/writePrecision" -set "$1" > /dev/null
    fi
    pimpleFoam > "log.precision.$1" 2>&1
}

cp system/controlDict system/controlDict.orig
runWith none
status=$?
digits=$(mostDigits)
check "[ $status -eq 0 ] && [ '$digits' = 10 ]" \
    "case writePrecision 6, none in the function object: the table has $digits digits, expected 10 (exit $status)"
runWith 7
status=$?
digits=$(mostDigits)
check "[ $status -eq 0 ] && [ '$digits' = 7 ]" \
    "function object's writePrecision 7: the table has $digits digits, expected 7 (exit $status)"
cp system/controlDict.orig system/controlDict
checkSummary
