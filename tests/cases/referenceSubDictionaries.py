#!/usr/bin/env python3
"""The sub-dictionaries of the function object that docs/reference.md documents: every
table row whose 'Allowed' column says "sub-dictionary", as the foamDictionary path of
the entry below the function object (grid, fibers/laydown, ...), one a line.

Usage: referenceSubDictionaries.py <docs/reference.md>
"""
import re
import sys

HEADING = re.compile(r"^#{2,3} (.*)$")
DICT_HEADING = re.compile(r"^`([\w.]+)`$")
ROW = re.compile(r"^\| `(\w+)` \| ([^|]*)\|")


def sub_dictionaries(text):
    """The paths of the entries documented as sub-dictionaries, in the page's order."""
    where, paths = None, []
    for line in text.splitlines():
        m = HEADING.match(line)
        if m:
            title = m.group(1).strip()
            d = DICT_HEADING.match(title)
            # the top level's table, a dictionary's (`grid`, `fibers.turbulence`), or
            # none of the function object's (the fvOption's, OpenFOAM's own, ...)
            where = "" if title == "Top-level entries" else d.group(1) if d else None
            continue
        m = ROW.match(line)
        if m and where is not None and "sub-dictionary" in m.group(2):
            paths.append("/".join(filter(None, where.split(".") + [m.group(1)])))
    return paths


if __name__ == "__main__":
    found = sub_dictionaries(open(sys.argv[1], encoding="utf-8").read())
    if not found:
        sys.exit("no sub-dictionaries found in " + sys.argv[1])
    print("\n".join(found))
