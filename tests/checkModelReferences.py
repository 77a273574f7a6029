#!/usr/bin/env python3
"""Every model reference resolves to the model pages. docs/model.md is the index: its table
of sections lists, for each section N, the page docs/model/NN-name.md and the equations
that page defines. The check reads the index and the pages and fails when

  - a section is listed twice, its page does not exist, is not named NN-..., or its title
    is not "# N. ..."; a page of docs/model/ is not listed; the index itself holds a
    numbered section ("## N.");
  - an equation tag ("(N)" or "(PN)" at the end of an indented equation line) is defined on
    two lines of the pages, or the index's equations column of a section is not exactly the
    tags its page defines;
  - a "docs/model.md sec. N" in the sources, tests, tools, benchmarks, validation and docs
    names no section, an equation cited as "eq. N", "eqs. N-M" or "eq. PN" is defined on no
    page, a "docs/model/NN-name.md" does not exist, or a link to a section's page is
    followed by "sec. M" of another section;
  - a file cites MODEL.md (a document outside the repository).

Usage: checkModelReferences.py <project dir>
       checkModelReferences.py --self-test   (the check catches each kind of break)
"""
import glob
import os
import re
import shutil
import sys
import tempfile

SUFFIXES = (".cpp", ".hpp", ".C", ".H", ".py", ".sh", ".md", ".txt")
FOLDERS = ("src", "tests", "tools", "bench", "validation", "docs", "tutorials")
INDEX = os.path.join("docs", "model.md")
PAGES = os.path.join("docs", "model")
# a break between the words of a reference: white space, and a comment's marks at a new line
GAP = r"(?:\s|//|#|\*)+"
EQUATION = re.compile(r"\beqs?\.\s*(P?\d+)(?:\s*[-–]\s*(P?\d+))?", re.I)
SECTION = re.compile(r"docs/model\.md,?" + GAP + r"secs?\.\s*(\d+)(?:\s*[-–]\s*(\d+))?")
PAGE_CITED = re.compile(r"docs/model/(\d+-[\w-]+\.md)")
PAGE_LINK = re.compile(r"\]\(([^)\s]*model/(\d+)-[\w-]+\.md)(?:#[^)\s]*)?\),?" + GAP
                       + r"secs?\.\s*(\d+)")
ROW = re.compile(r"^\|\s*(\d+)\s*\|\s*\[[^\]]*\]\(model/([^)#\s]+)\)\s*\|([^|]*)\|\s*$")
TAG = re.compile(r"^ {4,}\S.*\s\((P?\d+)\)\s*$")
FENCE = re.compile(r"^ {0,3}(```|~~~)")


def expand(column):
    """The tags of an equations column: "6–10, P7, P30" -> {"6", ..., "10", "P7", "P30"}."""
    tags = set()
    for item in column.split(","):
        item = item.strip()
        if item in ("", "–", "-"):
            continue
        match = re.fullmatch(r"(P?)(\d+)(?:\s*[-–]\s*(P?)(\d+))?", item)
        if not match:
            tags.add("?" + item)
            continue
        prefix, first, _, last = match.groups()
        for number in range(int(first), int(last or first) + 1):
            tags.add(f"{prefix}{number}")
    return tags


def defined_tags(path):
    """(tag, line number) of each equation a page defines."""
    in_fence = False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if FENCE.match(line):
                in_fence = not in_fence
                continue
            match = None if in_fence else TAG.match(line.rstrip("\n"))
            if match:
                yield match.group(1), number


def read_model(project):
    """The sections {N: page path} and equations {tag: where} of the index and its pages,
    and what is wrong with them."""
    failures = []
    index_path = os.path.join(project, INDEX)
    if not os.path.isfile(index_path):
        return {}, {}, [f"{INDEX} (the index of the model pages) does not exist"]
    sections, equations, listed = {}, {}, {}
    with open(index_path, encoding="utf-8") as f:
        index = f.read().splitlines()
    for number, line in enumerate(index, 1):
        where = f"{INDEX}:{number}"
        if re.match(r"^#{1,6}\s+\d+\.", line):
            failures.append(f"{where}: the index holds a numbered section; it belongs on "
                            f"its page in {PAGES}/")
        row = ROW.match(line)
        if not row:
            continue
        section, name, column = row.group(1), row.group(2), row.group(3)
        page = os.path.join(project, PAGES, name)
        if section in sections:
            failures.append(f"{where}: sec. {section} is listed twice")
            continue
        sections[section] = page
        listed[os.path.normpath(page)] = (section, column, where)
        if not name.startswith(f"{int(section):02d}-"):
            failures.append(f"{where}: the page of sec. {section} is {name}, not "
                            f"{int(section):02d}-<name>.md")
        if not os.path.isfile(page):
            failures.append(f"{where}: the page of sec. {section}, {PAGES}/{name}, "
                            f"does not exist")
    if not sections:
        failures.append(f"{INDEX}: no table of sections (| N | [title](model/NN-name.md) "
                        f"| equations |)")
    for page in sorted(glob.glob(os.path.join(project, PAGES, "*.md"))):
        rel = os.path.relpath(page, project)
        if os.path.normpath(page) not in listed:
            failures.append(f"{rel}: not listed in the table of sections of {INDEX}")
            continue
        section, column, where = listed[os.path.normpath(page)]
        with open(page, encoding="utf-8") as f:
            title = f.readline()
        if not title.startswith(f"# {section}. "):
            failures.append(f"{rel}:1: the title is not '# {section}. ...' (the index "
                            f"lists it as sec. {section})")
        tags = set()
        for tag, number in defined_tags(page):
            if tag in equations:
                failures.append(f"{rel}:{number}: eq. {tag} is defined again (first at "
                                f"{equations[tag]}); cite it as (eq. {tag})")
            else:
                equations[tag] = f"{rel}:{number}"
                tags.add(tag)
        column_tags = expand(column)
        for tag in sorted(column_tags - tags):
            failures.append(f"{where}: the index lists eq. {tag} for sec. {section}; "
                            f"{rel} does not define it")
        for tag in sorted(tags - column_tags):
            failures.append(f"{where}: {rel} defines eq. {tag}; the index does not list it "
                            f"for sec. {section}")
    return sections, equations, failures


def cited_files(project):
    for name in ("README.md", "CMakeLists.txt"):
        yield os.path.join(project, name)
    for folder in FOLDERS:
        for root, _, files in os.walk(os.path.join(project, folder)):
            for name in sorted(files):
                if name.endswith(SUFFIXES) or name == "CMakeLists.txt":
                    yield os.path.join(root, name)


def check_references(project, sections, equations):
    failures, checked = [], 0
    for path in cited_files(project):
        if not os.path.isfile(path) or os.path.abspath(path) == os.path.abspath(__file__):
            continue
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        rel = os.path.relpath(path, project)

        def where(match):
            return f"{rel}:{text.count(chr(10), 0, match.start()) + 1}"

        for line in text.splitlines():
            if "MODEL.md" in line:
                failures.append(f"{rel}: cites MODEL.md, which is not in the repository")
        for match in SECTION.finditer(text):
            for section in match.groups():
                if section:
                    checked += 1
                    if section not in sections:
                        failures.append(f"{where(match)}: docs/model.md has no "
                                        f"sec. {section}")
        for match in EQUATION.finditer(text):
            for eq in match.groups():
                if eq:
                    checked += 1
                    if eq not in equations:
                        failures.append(f"{where(match)}: eq. {eq} is defined on no page "
                                        f"of {PAGES}/")
        for match in PAGE_CITED.finditer(text):
            checked += 1
            if not os.path.isfile(os.path.join(project, PAGES, match.group(1))):
                failures.append(f"{where(match)}: {PAGES}/{match.group(1)} does not exist")
        for match in PAGE_LINK.finditer(text):
            checked += 1
            page, number, section = match.groups()
            if int(number) != int(section):
                failures.append(f"{where(match)}: the link to {page} is followed by "
                                f"sec. {section}; that page is sec. {int(number)}")
    return checked, failures


def check(project):
    sections, equations, failures = read_model(project)
    checked, more = check_references(project, sections, equations)
    summary = (f"{checked} references checked against {len(sections)} sections (pages of "
               f"{PAGES}/) and {len(equations)} equations")
    return summary, failures + more


def self_test():
    index = ("# The model\n\n| Sec. | Page | Equations |\n|---|---|---|\n"
             "| 1 | [Fibers](model/01-fibers.md) | 2, P1, P2 |\n"
             "| 2 | [Grid](model/02-grid.md) | 11–13 |\n")
    good = {
        "docs/model.md": index,
        "docs/model/01-fibers.md": "# 1. Fibers\n\n    a = b      (2)\n    c = d   (P1)\n"
                                   "\n    e = f     (P2)\n\nAs (2) says; (eq. P1) again.\n",
        "docs/model/02-grid.md": "# 2. Grid\n\n    g = h   (11)\n    i = j   (12)\n"
                                 "    k = l   (13)\n\n```\n    not = a tag   (14)\n```\n",
        "src/a.hpp": "// the tension (docs/model.md sec. 1, eq. 2; eqs. 11-13, eq. P2)\n"
                     "// the grid (docs/model.md\n// sec. 2); docs/model/02-grid.md\n",
        "docs/guide.md": "[model](model/02-grid.md#grid) sec. 2, [model](model.md) sec. 1\n",
    }
    cases = {
        "clean": ({}, None),
        "a missing section": ({"src/b.H": "// docs/model.md sec. 3\n"}, "has no sec. 3"),
        "a section across lines": ({"src/b.H": "// (docs/model.md\n//  sec. 4)\n"},
                                   "has no sec. 4"),
        "a missing equation": ({"src/b.H": "// eq. P3\n"}, "eq. P3 is defined on no page"),
        "an equation only in code": ({"src/b.H": "// eqs. 12-14\n"},
                                     "eq. 14 is defined on no page"),
        "a missing page": ({"src/b.H": "// docs/model/03-air.md\n"}, "does not exist"),
        "a link to another section": ({"docs/b.md": "[m](model/01-fibers.md) sec. 2\n"},
                                      "that page is sec. 1"),
        "an equation defined twice": ({"docs/model/02-grid.md": good["docs/model/02-grid.md"]
                                       + "    m = n   (P1)\n"}, "eq. P1 is defined again"),
        "an equation the index omits": ({"docs/model.md": index.replace("2, P1, P2", "2, P1")},
                                        "the index does not list it"),
        "a section listed twice": ({"docs/model.md": index + "| 2 | [G](model/02-grid.md) "
                                    "| 11–13 |\n"}, "sec. 2 is listed twice"),
        "a page not listed": ({"docs/model/03-air.md": "# 3. Air\n"}, "not listed"),
        "a wrong title": ({"docs/model/02-grid.md": "# 3. Grid\n"
                           + good["docs/model/02-grid.md"].split("\n", 1)[1]},
                          "the title is not '# 2. ...'"),
        "a section left in the index": ({"docs/model.md": index + "\n## 3. Air\n"},
                                        "the index holds a numbered section"),
    }
    failed = 0
    for name, (changes, expected) in cases.items():
        root = tempfile.mkdtemp()
        try:
            for path, text in {**good, **changes}.items():
                os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
                with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                    f.write(text)
            _, failures = check(root)
        finally:
            shutil.rmtree(root)
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
    summary, failures = check(project)
    print(summary)
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
