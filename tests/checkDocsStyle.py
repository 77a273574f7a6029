#!/usr/bin/env python3
"""The docs stay references: README.md, docs/*.md, docs/model/*.md (the model's pages) and
tutorials/*/README.md have no dated heading (a Markdown heading holding a date such as
2026-11-03, 3 Dec 2026, December 2026, or the word "session"), no commit hash (7 to 40 hex
digits with at least one letter and one digit, standing alone as a word or in backticks),
no git branch name (a quoted name after or before the word "branch", or "merge branch"),
and docs/performance.md stays at most 16 kB. History belongs in the commit messages. Every
page of docs/ and docs/model/ is checked, so a new page is covered as soon as it exists.

Usage: checkDocsStyle.py <project dir>
       checkDocsStyle.py --self-test   (the check catches each kind of violation)
Prints file:line and what is wrong for each violation; exits 1 if there is any.
"""
import glob
import os
import re
import sys
import tempfile

PERFORMANCE_LIMIT = 16 * 1024  # bytes of docs/performance.md

MONTH = (r"(?:Jan(?:uary)?|Feb(?:ruary)?|Mar(?:ch)?|Apr(?:il)?|May|June?|July?|"
         r"Aug(?:ust)?|Sep(?:t(?:ember)?)?|Oct(?:ober)?|Nov(?:ember)?|Dec(?:ember)?)")
DATE = re.compile(
    r"\b\d{4}-\d{1,2}-\d{1,2}\b"                           # 2026-11-03
    r"|\b\d{1,2}[./]\d{1,2}[./]\d{4}\b"                    # 03.11.2026, 3/11/2026
    r"|\b\d{4}/\d{1,2}/\d{1,2}\b"                          # 2026/11/03
    r"|\b\d{1,2}(?:st|nd|rd|th)?\.?\s+" + MONTH + r"\.?,?\s+\d{4}\b"  # 3 Dec 2026
    r"|\b" + MONTH + r"\.?\s+(?:\d{1,2}(?:st|nd|rd|th)?,?\s+)?\d{4}\b"  # Dec 3, 2026; December 2026
    r"|\bsessions?\b",
    re.I)
# A git-hash-like token: not part of a longer word, path, number or colour (#a1b2c3d4),
# nor a number in scientific notation (12345e67).
HASH = re.compile(r"(?<![\w#\-./+])([0-9a-f]{7,40})(?![\w\-/+]|\.\w)", re.I)
SCIENTIFIC = re.compile(r"^\d+e\d+$", re.I)
# A git branch by name: "branch `docs`", "branch: 'nolive'", "the `docs` branch",
# "Merge branch" (not "both branches", "branch-free": no quoted name beside it)
BRANCH = re.compile(
    r"\bbranch(?:es)?\s*:?\s+[`'\"][\w./-]+[`'\"]"
    r"|[`'\"][\w./-]+[`'\"]\s+branch\b"
    r"|\bmerge\s+branch\b",
    re.I)
ATX_HEADING = re.compile(r"^ {0,3}#{1,6}(?:\s|$)")
SETEXT_UNDERLINE = re.compile(r"^ {0,3}(?:=+|-+)\s*$")
FENCE = re.compile(r"^ {0,3}(```|~~~)")


def checked_files(project):
    names = ["README.md"] + sorted(glob.glob(os.path.join(project, "docs", "*.md")))
    names += sorted(glob.glob(os.path.join(project, "docs", "model", "*.md")))
    names += sorted(glob.glob(os.path.join(project, "tutorials", "*", "README.md")))
    for name in names:
        path = os.path.join(project, name)
        if os.path.isfile(path):
            yield path


def hashes(line):
    found = []
    for token in HASH.findall(line):
        if (re.search(r"[a-f]", token, re.I) and re.search(r"\d", token)
                and not SCIENTIFIC.match(token)):
            found.append(token)
    return found


def headings(lines):
    """(line number, text) of each Markdown heading outside fenced code."""
    in_fence = False
    for index, line in enumerate(lines):
        if FENCE.match(line):
            in_fence = not in_fence
            continue
        if in_fence:
            continue
        if ATX_HEADING.match(line):
            yield index + 1, line
        elif (SETEXT_UNDERLINE.match(line) and index > 0 and lines[index - 1].strip()
              and not lines[index - 1].lstrip().startswith(("|", "-", "*", "+", ">", "#"))):
            yield index, lines[index - 1]


def check_file(path, project):
    where = os.path.relpath(path, project)
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = f.read().splitlines()
    failures = []
    for number, text in headings(lines):
        match = DATE.search(text)
        if match:
            failures.append(f"{where}:{number}: dated heading ('{match.group(0)}'): "
                            f"{text.strip()}")
    for number, line in enumerate(lines, 1):
        for token in hashes(line):
            failures.append(f"{where}:{number}: commit hash '{token}' (history belongs in "
                            f"commit messages)")
        for match in BRANCH.finditer(line):
            failures.append(f"{where}:{number}: branch name ('{match.group(0)}'): history "
                            f"belongs in commit messages")
    if os.path.relpath(path, project) == os.path.join("docs", "performance.md"):
        size = os.path.getsize(path)
        if size > PERFORMANCE_LIMIT:
            failures.append(f"{where}:1: {size} bytes, more than {PERFORMANCE_LIMIT}: "
                            f"keep current figures, move history to commit messages")
    return failures


def check(project):
    failures, files = [], 0
    for path in checked_files(project):
        files += 1
        failures += check_file(path, project)
    return files, failures


def self_test():
    clean = ("# Performance reference\n\n## Deposit\n\n| figure | spread |\n|---|---|\n"
             "| 1.11 M parcels/s | 1e-17, 12345e6, 2.5e10 |\n\nColour #a1b2c3 and #a1b2c3d4, "
             "a path src/core/ab12cd3, 0x1f2e3d4c, deadbeef, 1234567, v1912, "
             "uuid 123e4567-e89b-12d3-a456-426614174000; exact in both branches, branch-free "
             "code.\n\nSetext heading\n---\n\n"
             "```\n# 2026-11-03 a shell comment in code\n```\n")
    cases = {
        "clean": (clean, None),
        "ISO-dated heading": (clean + "\n## Figures of 2026-11-03\n", "dated heading"),
        "day-month heading": (clean + "\n### Rerun 3 Dec 2026\n", "dated heading"),
        "month-year heading": (clean + "\n## December 2026\n", "dated heading"),
        "session heading": (clean + "\n## What this session measured\n", "dated heading"),
        "setext dated heading": (clean + "\nResults, 2026-11-03\n===\n", "dated heading"),
        "bare hash": (clean + "\nMeasured at fe903b6 with load 2.\n", "commit hash"),
        "hash in backticks": (clean + "\nbefore `bd02c6f1a2`, after.\n", "commit hash"),
        "full hash": (clean + "\n(" + "5ae65ca" * 5 + "12345)\n", "commit hash"),
        "branch name": (clean + "\nMeasured on branch `balanced-blocks`.\n", "branch name"),
        "named branch": (clean + "\nThe 'nolive' branch keeps it.\n", "branch name"),
        "merge branch": (clean + "\nAfter Merge branch of the work.\n", "branch name"),
    }
    big = clean + ("Figures only, no history here; " * 3 + "\n") * 200
    big = big[:17 * 1024 - 1] + "\n"  # a 17 kB performance.md
    cases["oversized performance.md"] = (big, "bytes, more than")
    failed = 0
    for name, (text, expected) in cases.items():
        with tempfile.TemporaryDirectory() as project:
            os.makedirs(os.path.join(project, "docs"))
            with open(os.path.join(project, "README.md"), "w", encoding="utf-8") as f:
                f.write("# Project\n")
            with open(os.path.join(project, "docs", "performance.md"), "w",
                      encoding="utf-8") as f:
                f.write(text)
            _, failures = check(project)
        if expected is None:
            ok = not failures
        else:
            ok = len(failures) == 1 and expected in failures[0]
        print(f"{'ok' if ok else 'FAILED'}: {name}: "
              f"{'passes' if not failures else '; '.join(failures)}")
        failed += not ok
    print(f"self-test: {len(cases) - failed} of {len(cases)} cases as expected")
    return 1 if failed else 0


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--self-test":
        return self_test()
    project = sys.argv[1] if len(sys.argv) > 1 else "."
    files, failures = check(project)
    print(f"{files} files checked: headings without dates or sessions, no commit hashes, "
          f"no branch names, docs/performance.md at most {PERFORMANCE_LIMIT} bytes")
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
