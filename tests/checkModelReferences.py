#!/usr/bin/env python3
"""Every model reference resolves to docs/model.md: each "docs/model.md sec. N" names a
section "## N." of docs/model.md, and each equation cited as "eq. N", "eqs. N-M" or
"eq. PN" in the sources, tests, tools, benchmarks, validation and docs is tagged "(N)"
in docs/model.md. No file may cite MODEL.md (a document outside the repository).

Usage: checkModelReferences.py <project dir>
"""
import os
import re
import sys

SUFFIXES = (".cpp", ".hpp", ".C", ".H", ".py", ".sh", ".md", ".txt")
FOLDERS = ("src", "tests", "tools", "bench", "validation", "docs", "tutorials")
EQUATION = re.compile(r"\beqs?\.\s*(P?\d+)(?:\s*[-–]\s*(P?\d+))?", re.I)
SECTION = re.compile(r"docs/model\.md,?\s+secs?\.\s*(\d+)")


def cited_files(project):
    for name in ("README.md", "CMakeLists.txt"):
        yield os.path.join(project, name)
    for folder in FOLDERS:
        for root, _, files in os.walk(os.path.join(project, folder)):
            for name in files:
                if name.endswith(SUFFIXES) or name == "CMakeLists.txt":
                    yield os.path.join(root, name)


def main():
    project = sys.argv[1] if len(sys.argv) > 1 else "."
    model_path = os.path.join(project, "docs", "model.md")
    if not os.path.isfile(model_path):
        print("FAILED: docs/model.md does not exist")
        return 1
    with open(model_path, encoding="utf-8") as f:
        model = f.read()
    sections = set(re.findall(r"^## (\d+)\.", model, re.M))
    equations = set(re.findall(r"\((P?\d+)\)", model))
    failures, checked = [], 0
    for path in cited_files(project):
        if os.path.samefile(path, model_path) or os.path.samefile(path, __file__):
            continue
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                where = f"{os.path.relpath(path, project)}:{number}"
                if "MODEL.md" in line:
                    failures.append(f"{where}: cites MODEL.md, which is not in the repository")
                for section in SECTION.findall(line):
                    checked += 1
                    if section not in sections:
                        failures.append(f"{where}: docs/model.md has no sec. {section}")
                for first, last in EQUATION.findall(line):
                    for eq in (first, last):
                        if not eq:
                            continue
                        checked += 1
                        if eq not in equations:
                            failures.append(f"{where}: eq. {eq} is not in docs/model.md")
    print(f"{checked} references checked against {len(sections)} sections and "
          f"{len(equations)} equations of docs/model.md")
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
