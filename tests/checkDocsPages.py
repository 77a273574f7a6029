#!/usr/bin/env python3
"""The documentation's pages stay what they are for (docs/development.md, the
documentation checks):

  readmeSize  README.md is the front door: at most README_LIMIT bytes (10 kB); the rest
              belongs in docs/.
  links       every relative Markdown link of README.md, docs/*.md, docs/model/*.md and
              tutorials/*/README.md names a file or folder of the repository, and its
              #anchor a heading of that file (GitHub's anchors: lower case, punctuation
              dropped, spaces as hyphens, repeats numbered).
  layout      docs/development.md names every folder of src/ (as `src/.../`).

Usage: checkDocsPages.py readmeSize|links|layout <project dir>
       checkDocsPages.py --self-test   (each check catches what it is for)
Prints file:line and what is wrong for each violation; exits 1 if there is any.
"""
import os
import re
import sys
import tempfile

# The pages the docs style check reads, and its fence pattern
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checkDocsStyle import FENCE, checked_files as pages  # noqa: E402

README_LIMIT = 10 * 1024  # bytes of README.md
LAYOUT_PAGE = os.path.join("docs", "development.md")

LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^ {0,3}#{1,6}\s+(.*?)\s*#*\s*$")


def outside_code(text):
    """(line number, line) of the lines outside fenced code, inline code blanked."""
    in_fence = False
    for number, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            in_fence = not in_fence
            continue
        if not in_fence:
            yield number, re.sub(r"`[^`]*`", lambda m: " " * len(m.group(0)), line)


def anchors(path):
    """The anchors GitHub gives the headings of a Markdown file."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    found, seen = set(), {}
    in_fence = False
    for line in text.splitlines():
        if FENCE.match(line):
            in_fence = not in_fence
            continue
        heading = None if in_fence else HEADING.match(line)
        if not heading:
            continue
        title = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading.group(1))  # link text
        slug = re.sub(r"[^\w\- ]", "", title.lower()).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        found.add(slug if count == 0 else f"{slug}-{count}")
    return found


def check_links(project):
    failures, checked = [], 0
    for path in pages(project):
        where = os.path.relpath(path, project)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for number, line in outside_code(text):
            for target in LINK.findall(line):
                if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):
                    continue  # http:, https:, mailto:
                checked += 1
                file_part, _, anchor = target.partition("#")
                linked = (os.path.normpath(os.path.join(os.path.dirname(path), file_part))
                          if file_part else path)
                if not os.path.exists(linked):
                    failures.append(f"{where}:{number}: link '{target}': "
                                    f"{os.path.relpath(linked, project)} does not exist")
                elif anchor and (not linked.endswith(".md")
                                 or anchor not in anchors(linked)):
                    failures.append(f"{where}:{number}: link '{target}': no heading "
                                    f"'#{anchor}' in {os.path.relpath(linked, project)}")
    return f"{checked} relative links checked", failures


def check_readme_size(project):
    size = os.path.getsize(os.path.join(project, "README.md"))
    failures = []
    if size > README_LIMIT:
        failures.append(f"README.md:1: {size} bytes, more than {README_LIMIT}: the README "
                        f"is the front door; move the details to docs/ and link them")
    return f"README.md: {size} bytes (at most {README_LIMIT})", failures


def check_layout(project):
    page = os.path.join(project, LAYOUT_PAGE)
    with open(page, encoding="utf-8") as f:
        text = f.read()
    named = set(re.findall(r"`(src(?:/[\w.-]+)*)/?`", text))
    failures, folders = [], 0
    for root, dirs, _ in os.walk(os.path.join(project, "src")):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d != "lnInclude"
                         and not d.startswith("Make"))
        folder = os.path.relpath(root, project).replace(os.sep, "/")
        folders += 1
        if folder not in named:
            failures.append(f"{LAYOUT_PAGE}: folder `{folder}/` is not named (one line in "
                            f"Source layout)")
    return f"{folders} folders of src/ looked for in {LAYOUT_PAGE}", failures


CHECKS = {"readmeSize": check_readme_size, "links": check_links, "layout": check_layout}


def self_test():
    def project(files):
        root = tempfile.mkdtemp()
        for name, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(root, name)) or root, exist_ok=True)
            with open(os.path.join(root, name), "w", encoding="utf-8") as f:
                f.write(text)
        return root

    guide = ("# Guide\n\n## Restart: what is kept\n\n## `fibers.injectors.<name>`\n\n"
             "## Restart: what is kept\n\n```\n# not a heading\n```\n")
    layout = "| `src/` | x |\n| `src/core/` | x |\n| `src/core/grid/` | x |\n"
    good = {
        "README.md": "# P\n\n[guide](docs/guide.md#restart-what-is-kept), "
                     "[name](docs/guide.md#fibersinjectorsname), [again]"
                     "(docs/guide.md#restart-what-is-kept-1), [web](https://x.org/a#b), "
                     "`[code](nowhere.md)`\n",
        "docs/guide.md": guide,
        "docs/development.md": layout,
        "docs/model/01-fiberDynamics.md": "# 1. Fibers\n\n"
                                          "[guide](../guide.md#restart-what-is-kept)\n",
        "src/core/grid/a.hpp": "",
    }
    cases = {
        "clean": ({}, None, None),
        "a 10.5 kB README": ({"README.md": "# P\n" + "x" * 10750 + "\n"}, "readmeSize",
                             "bytes, more than"),
        "a link to a missing file": ({"docs/guide.md": guide + "[m](model.md)\n"}, "links",
                                     "does not exist"),
        "a link to a missing heading": ({"docs/guide.md": guide + "[r](#restart)\n"},
                                        "links", "no heading '#restart'"),
        "a model page's link as from docs/": (
            {"docs/model/01-fiberDynamics.md": "# 1. Fibers\n\n[guide](guide.md)\n"}, "links",
            "docs/model/guide.md does not exist"),
        "a heading in code is none": ({"docs/guide.md": guide + "[n](#not-a-heading)\n"},
                                      "links", "no heading"),
        "a folder not named": ({"src/openfoam/stages/a.H": ""}, "layout",
                               "`src/openfoam/` is not named"),
    }
    failed = 0
    for name, (changes, check, expected) in cases.items():
        root = project({**good, **changes})
        results = {key: CHECKS[key](root)[1] for key in CHECKS}
        failures = [f for key in CHECKS for f in results[key]]
        if expected is None:
            ok = not failures
        else:
            ok = bool(results[check]) and expected in results[check][0] and all(
                not results[key] for key in CHECKS if key != check)
        print(f"{'ok' if ok else 'FAILED'}: {name}: "
              f"{'passes' if not failures else '; '.join(failures)}")
        failed += not ok
    print(f"self-test: {len(cases) - failed} of {len(cases)} cases as expected")
    return 1 if failed else 0


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--self-test":
        return self_test()
    if len(sys.argv) < 2 or sys.argv[1] not in CHECKS:
        print(__doc__)
        return 2
    project = sys.argv[2] if len(sys.argv) > 2 else "."
    summary, failures = CHECKS[sys.argv[1]](project)
    print(summary)
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
