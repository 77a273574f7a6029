#!/usr/bin/env bash
# Make/files (wmake) must list every source of the core and the OpenFOAM layer
# that CMake builds, so the OpenFOAM library and the unit-tested core never differ.
cd "$(dirname "$0")/.." || exit 1
passed=0; failed=0
while IFS= read -r src; do
    if grep -qx "$src" Make/files; then
        passed=$((passed+1))
    else
        failed=$((failed+1)); echo "FAILED: $src is not in Make/files"
    fi
done < <(find src/core src/openfoam \( -name '*.cpp' -o -name '*.C' \) | sort)
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
