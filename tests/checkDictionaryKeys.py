#!/usr/bin/env python3
"""Every entry a reader of the function object's dictionary reads is in a list of
allowed entries that checkKeys() holds the dictionaries to (src/openfoam/settings/
dictionaryKeys.H): a key read but not listed would stop every run that gives it.
(One reader may read a sub-dictionary of a dictionary listed in another's file.) Looks for string keys passed to the checked readers (getPositive,
getChoice, ...) and to the dictionary's look-ups (lookupOrDefault, get, found,
findDict, subOrEmptyDict); the lists are the string literals of a `wordList ...Keys`
or of a `checkKeys(dict, {...})`.

Usage: checkDictionaryKeys.py <project dir>
"""
import os
import re
import sys

# The readers of the function object's dictionary (not of its restart state)
READERS = (
    "src/openfoam/settings/gridSettings.C",
    "src/openfoam/settings/collisionSettings.C",
    "src/openfoam/settings/fiberSettings.C",
    "src/openfoam/settings/turbulenceSettings.C",
    "src/openfoam/airSampler/airSampler.C",
    "src/openfoam/dropletFiberCollision/dropletFiberCollision.C",
)
CHECKED_READ = re.compile(
    r"\b(?:getPositive|getNonNegative|getCheckedScalar|getLabelInRange|getSwitch"
    r"|getChoice|readSource)\s*\(\s*[\w.>-]+\s*,\s*\"(\w+)\""
)
LOOKUP = re.compile(
    r"\w\.(?:lookupOrDefault|get|found|findDict|subOrEmptyDict|subDict|findEntry|lookup)"
    r"(?:<[^>(]*>)?\(\s*\"(\w+)\""
)
KEY_LIST = re.compile(r"wordList\s+\w*Keys\s*\{([^}]*)\}|checkKeys\s*\(\s*\w+\s*,\s*\{([^}]*)\}")
LITERAL = re.compile(r"\"(\w+)\"")


def main():
    project = sys.argv[1] if len(sys.argv) > 1 else "."
    texts = {path: open(os.path.join(project, path)).read() for path in READERS}
    allowed = set()
    for text in texts.values():
        for match in KEY_LIST.finditer(text):
            allowed.update(LITERAL.findall(match.group(1) or match.group(2)))
    passed = failed = 0
    for path, text in texts.items():
        read = set(CHECKED_READ.findall(text)) | set(LOOKUP.findall(text))
        if not read:
            failed += 1
            print(f"FAILED: {path}: no keys read found")
        for key in sorted(read):
            if key in allowed:
                passed += 1
            else:
                failed += 1
                print(f"FAILED: {path} reads entry '{key}', which is in no list of allowed keys")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
