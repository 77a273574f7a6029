#!/usr/bin/env bash
# Every entry that docs/reference.md documents as a sub-dictionary stops the run,
# naming it, when it is given as anything else (one word, a number, a list): one
# rule for all of them (dictionaryChecks.H findSubDict), none ignored with its
# defaults in force. The sub-dictionaries are found in the reference
# (referenceSubDictionaries.py), so that a new one is tried without editing this.
# Usage: checkSubDictionaries.sh CASE_DIR WORK_DIR REFERENCE_MD (runs a copy)
set -uo pipefail
here="$(cd "${0%/*}" && pwd)"
reference="$(cd "$(dirname "$3")" && pwd)/$(basename "$3")"
# shellcheck disable=SC1091
. "$here/lib/prepareCase.sh"
prepareCaseCopy "$1" "$2"
cp system/controlDict system/controlDict.good
fo=functions/dropletFiber

# tryAs PATH VALUE: PATH (below the function object) given as VALUE must stop the
# run with an error naming it
tryAs() {
    local path="$1" value="$2" how=-add
    cp system/controlDict.good system/controlDict
    # a parent the case does not give (collision for collision/spread): added empty
    if [ "${path%/*}" != "$path" ] \
        && ! foamDictionary system/controlDict -entry "$fo/${path%/*}" > /dev/null 2>&1
    then
        foamDictionary system/controlDict -entry "$fo/${path%/*}" -add "{}" > /dev/null
    fi
    foamDictionary system/controlDict -entry "$fo/$path" > /dev/null 2>&1 && how=-set
    foamDictionary system/controlDict -entry "$fo/$path" "$how" "$value" > /dev/null \
        || { echo "FAILED: cannot set $path to $value"; checksFailed=$((checksFailed + 1)); return; }
    foamListTimes -rm > /dev/null 2>&1
    rm -rf postProcessing
    pimpleFoam > log.bad 2>&1
    expectFatalIOError $? log.bad \
        "Entry '${path##*/}' is '.*': it must be a sub-dictionary, ${path##*/} \{ ... \}" \
        "$path = $value"
}

paths="$("$PY" "$here/referenceSubDictionaries.py" "$reference")" \
    || { echo "FAILED: no sub-dictionaries read from $reference"; exit 1; }
n=0
for path in $paths; do
    tryAs "$path" on
    tryAs "$path" 1
    n=$((n + 1))
done
check "[ $n -ge 8 ]" "only $n sub-dictionaries found in the reference (grid, collision, air, fibers and four of fibers at least)"
checkSummary || exit 1
