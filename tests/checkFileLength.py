#!/usr/bin/env python3
"""Files of one concept: no source file under the given folders is longer than the limit
(lines). Prints the longest files and every one over the limit.

Usage: checkFileLength.py <limit> <folder>...
       checkFileLength.py --self-test   (a file over the limit is caught)
"""
import os
import sys
import tempfile

SUFFIXES = (".C", ".H", ".cpp", ".hpp")


def lengths(folders):
    """[(lines, path)] of every source file under folders, longest first."""
    found = []
    for folder in folders:
        for root, _, files in os.walk(folder):
            for name in files:
                if name.endswith(SUFFIXES):
                    path = os.path.join(root, name)
                    with open(path, encoding="utf-8", errors="replace") as f:
                        found.append((sum(1 for _ in f), path))
    return sorted(found, reverse=True)


def check(limit, folders, out=sys.stdout):
    found = lengths(folders)
    print(f"{len(found)} files; the longest:", file=out)
    for n, path in found[:5]:
        print(f"    {n} lines  {path}", file=out)
    over = [(n, p) for n, p in found if n > limit]
    for n, path in over:
        print(f"FAILED: {path} is {n} lines (limit {limit}): split it by concept", file=out)
    return 1 if over or not found else 0


def self_test():
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "long.C"), "w") as f:
            f.write("\n" * 12)
        with open(os.path.join(d, "short.H"), "w") as f:
            f.write("\n" * 3)
        with open(os.devnull, "w") as null:
            caught = check(10, [d], null) == 1
            passed = check(12, [d], null) == 0
    print("self-test: a file over the limit %s, one at it %s"
          % ("caught" if caught else "NOT caught", "passes" if passed else "FAILS"))
    return 0 if caught and passed else 1


if __name__ == "__main__":
    if sys.argv[1:2] == ["--self-test"]:
        sys.exit(self_test())
    sys.exit(check(int(sys.argv[1]), sys.argv[2:]))
