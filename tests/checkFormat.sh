#!/usr/bin/env bash
# One layout (.clang-format): every C++ file of the core, the tests, tools, benchmarks and
# validation is exactly as Debian's clang-format 14 lays it out; the OpenFOAM layer
# (src/openfoam and applications, OpenFOAM's own hand layout, which clang-format
# cannot express) has Allman braces, no tabs and no trailing blanks. Prints each file
# that differs and how to fix it. Exit 77 (skipped) without clang-format 14: other
# versions lay out differently.
cd "$(dirname "$0")/.." || exit 1
command -v clang-format >/dev/null || { echo "SKIPPED: no clang-format (Debian package clang-format)"; exit 77; }
major=$(clang-format --version | sed -n 's/.*version \([0-9]*\)\..*/\1/p')
[ "$major" = 14 ] || { echo "SKIPPED: clang-format $major; the layout is checked with version 14"; exit 77; }

passed=0; failed=0
while IFS= read -r file; do
    if clang-format --dry-run --Werror "$file" >/dev/null 2>&1; then
        passed=$((passed+1))
    else
        failed=$((failed+1)); echo "FAILED: $file is not laid out as .clang-format says (clang-format -i $file)"
    fi
done < <(find src/core tests/unit tools bench validation \( -name '*.cpp' -o -name '*.hpp' \) | sort)

while IFS= read -r file; do
    bad=$(grep -nP '\t| +$|[^\s{]\s*\{\s*$' "$file" | head -3)
    if [ -z "$bad" ]; then
        passed=$((passed+1))
    else
        failed=$((failed+1)); echo "FAILED: $file: tab, trailing blank or brace not on a line of its own:"; echo "$bad"
    fi
done < <(find src/openfoam applications \( -name '*.C' -o -name '*.H' \) | sort)
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
