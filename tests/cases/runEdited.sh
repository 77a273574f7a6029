#!/usr/bin/env bash
#------------------------------------------------------------------------------
# runEdited.sh - runCase.sh on a copy of a case whose controlDict is edited first
# (foamDictionary -set, or -add for a new entry), e.g. the function object's entries.
#
# Usage: runEdited.sh CASE_DIR WORK_DIR MODE 'ENTRY VALUE' ['ENTRY VALUE' ...] -- [CHECK_COMMAND ...]
#   ENTRY: a controlDict entry path (functions/dropletFiber/collision/depletion),
#   VALUE: its new value as foamDictionary takes it.
#------------------------------------------------------------------------------
set -euo pipefail
caseDir="$1"; workDir="$2"; mode="$3"; shift 3
here="$(cd "${0%/*}" && pwd)"
# shellcheck disable=SC1091
. "$here/../../bin/functions.sh"
loadFoamEnvironment
source="$(mktemp -d)"
trap 'rm -rf "$source"' EXIT
cp -r "$caseDir"/. "$source"
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do
    entry="${1%% *}"; value="${1#* }"
    # -add leaves an entry that exists as it is: -set that one
    how=-add
    foamDictionary "$source/system/controlDict" -entry "$entry" > /dev/null 2>&1 && how=-set
    foamDictionary "$source/system/controlDict" -entry "$entry" "$how" "$value" > /dev/null \
        || die "cannot set $entry to $value"
    shift
done
[ "$#" -gt 0 ] && shift
"$here/runCase.sh" "$source" "$workDir" "$mode" "$@"
