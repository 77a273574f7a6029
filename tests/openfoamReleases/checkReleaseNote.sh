#!/usr/bin/env bash
#------------------------------------------------------------------------------
# checkReleaseNote.sh - the start-up note on the OpenFOAM release (CTest
# build.openfoamReleases.runTimeNote): releaseNoteTest.C against the loaded
# OpenFOAM (v1912 here), with src/openfoam/settings/openfoamRelease.C compiled as
# wmake compiles the library (compileFlags.mk) but for another release
# (-DOPENFOAM=2312), so that the note a library built for one release and loaded
# by another logs is seen at run time, once; and its text for each pair of
# releases. Then the same with the loaded release's own number: nothing to say
# on v1912.
#
# Usage: checkReleaseNote.sh <work folder>
# Exit:  0 passed, 1 failed, 77 skipped (no OpenFOAM environment loaded)
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
project="$(cd "$here/../.." && pwd)"
work="${1:?usage: $0 <work folder>}"
if [ -z "${WM_PROJECT_DIR:-}" ] || [ -z "${FOAM_LIBBIN:-}" ]; then
    echo "SKIPPED: no OpenFOAM environment loaded (WM_PROJECT_DIR, FOAM_LIBBIN)"
    exit 77
fi
mkdir -p "$work"
work="$(cd "$work" && pwd)"
cd "$project"
line="$(make -s -f "$here/compileFlags.mk" WM_PROJECT_DIR="$WM_PROJECT_DIR" \
    MAKE_DIR="$project/Make" OPTIONS="$work/options" compileLine)"
running="$(sed -n 's/.*-DOPENFOAM=\([0-9]*\).*/\1/p' <<< "$line")"
[ -n "$running" ] || { echo "FAILED: no -DOPENFOAM in the compile line: $line"; exit 1; }
# shellcheck disable=SC2086  # the compile line is a list of words
$line -c "$here/releaseNoteTest.C" -o "$work/releaseNoteTest.o"
status=0
for compiled in 2312 "$running"; do
    echo "== openfoamRelease.C compiled for $compiled, run with libOpenFOAM of $WM_PROJECT_DIR"
    # shellcheck disable=SC2086  # the compile line is a list of words
    $line -UOPENFOAM -DOPENFOAM="$compiled" -c src/openfoam/settings/openfoamRelease.C \
        -o "$work/openfoamRelease.$compiled.o"
    g++ "$work/releaseNoteTest.o" "$work/openfoamRelease.$compiled.o" \
        -L"$FOAM_LIBBIN" -lOpenFOAM -ldl -o "$work/releaseNoteTest.$compiled"
    LD_LIBRARY_PATH="$FOAM_LIBBIN:${LD_LIBRARY_PATH:-}" \
        "$work/releaseNoteTest.$compiled" "$compiled" || status=1
done
exit $status
