#!/usr/bin/env python3
"""The function object's dictionary entries: read, allowed and documented alike.

1. Every entry a reader of the function object's dictionary reads is in a list of
   allowed entries that checkKeys() holds the dictionaries to (src/openfoam/settings/
   dictionaryKeys.H): a key read but not listed would stop every run that gives it.
   (One reader may read a sub-dictionary of a dictionary listed in another's file.)
   Looks for string keys passed to the checked readers (getPositive, getChoice, ...)
   and to the dictionary's look-ups (lookupOrDefault, get, found, findDict,
   subOrEmptyDict); the lists are the string literals of a `wordList ...Keys` or of a
   `checkKeys(dict, {...})`.
2. docs/reference.md, the one reference of the entries, documents exactly the entries
   the code accepts: every allowed entry of every dictionary (top level, grid,
   collision, air, fibers, fibers.turbulence, each injector and fixed fiber) has a row
   in the table of its dictionary, and no row names an entry the code does not accept.
   The lists are found in every file of src/openfoam by their names (KEY_LISTS says
   which dictionary each holds). A table's dictionary is the `name` in backticks in the
   heading above it (none: the top level).
3. Where the code states them as literals, the documented defaults and allowed values
   are the code's: getChoice's choices and default, getSwitch's default, the default
   and the bounds of getLabelInRange, the defaults of getNonNegative, getPositive and
   getCheckedScalar.

Usage: checkDictionaryKeys.py <project dir>
       checkDictionaryKeys.py --self-test <project dir>   (part 2 and 3 catch a missing
       row, an unknown row, a wrong default and a wrong choice)
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
    "src/openfoam/airSampler/airSamplerSettings.C",
    "src/openfoam/dropletFiberCollision/dropletFiberCollision.C",
    "src/openfoam/stages/sprayParcels/sprayParcels.C",
    "src/openfoam/stages/couplingGrid/couplingGrid.C",
    "src/openfoam/stages/fiberPopulation/fiberPopulation.C",
    "src/openfoam/stages/couplingOutput/couplingOutput.C",
    "src/openfoam/stages/couplingRestart/couplingRestart.C",
    "src/openfoam/stages/airReaction/airReaction.C",
    "src/openfoam/fiberDragSource/fiberDragSource.C",
    "src/openfoam/stages/fiberLaydown/fiberLaydown.C",
)
CHECKED_READ = re.compile(
    r"\b(?:getPositive|getNonNegative|getCheckedScalar|getLabelInRange|getSwitch"
    r"|getChoice|readSource|optionalSubDict|findSubDict)\s*\(\s*[\w.>-]+\s*,\s*\"(\w+)\""
)
LOOKUP = re.compile(
    r"\w\.(?:lookupOrDefault|get|found|findDict|subOrEmptyDict|subDict|findEntry|lookup)"
    r"(?:<[^>(]*>)?\(\s*\"(\w+)\""
)
KEY_LIST = re.compile(r"wordList\s+\w*Keys\s*\{([^}]*)\}|checkKeys\s*\(\s*\w+\s*,\s*\{([^}]*)\}")
LITERAL = re.compile(r"\"(\w+)\"")


def check_lists_read(project):
    """Part 1: (passed, failures) of the keys the READERS read against the lists (the
    lists of every file of src/openfoam)."""
    passed, failures = 0, []
    texts = {}
    for path in READERS:
        if os.path.isfile(os.path.join(project, path)):
            texts[path] = open(os.path.join(project, path), encoding="utf-8").read()
        else:
            failures.append(f"{path} (READERS) does not exist: name the files that read "
                            f"the function object's dictionary")
    allowed = set()
    for text in source_texts(project).values():
        for match in KEY_LIST.finditer(text):
            allowed.update(LITERAL.findall(match.group(1) or match.group(2)))
    for path, text in texts.items():
        read = set(CHECKED_READ.findall(text)) | set(LOOKUP.findall(text))
        if not read:
            failures.append(f"{path}: no keys read found")
        for key in sorted(read):
            if key in allowed:
                passed += 1
            else:
                failures.append(f"{path} reads entry '{key}', which is in no list of allowed keys")
    return passed, failures


# The dictionary each list of allowed keys holds ("": the function object's own level);
# a list name here is a `wordList <name>` or the dictionary argument of
# `checkKeys(<name>, {...})`. The material keys are allowed in fibers and in each
# injector and fixed fiber (fiberSettings.C: fiberMotionKeys, checkFiberSourceKeys).
INJECTOR, FIXED = "fibers.injectors.<name>", "fibers.fixed.<name>"
KEY_LISTS = {
    # the top level: OpenFOAM's own and each stage's (the function object joins them)
    "openFoamKeys": [""],
    "sprayKeys": [""],
    "gridStageKeys": [""],
    "captureKeys": [""],
    "motionKeys": [""],
    "outputKeys": [""],
    "restartKeys": [""],
    "gridKeys": ["grid"],
    "collisionKeys": ["collision"],
    "spreadKeys": ["collision.spread"],
    "airDict": ["air"],
    "materialKeys": ["fibers", INJECTOR, FIXED],
    # fibers: each stage's of the fibers
    "fiberSolverKeys": ["fibers"],
    "fiberSourceKeys": ["fibers"],
    "couplingKeys": ["fibers"],
    "beltKeys": ["fibers"],
    "injectorKeys": [INJECTOR],
    "fixedFiberKeys": [FIXED],
    "turbulenceKeys": ["fibers.turbulence"],
    "fiberDragSourceKeys": ["fiberDragSource"],
    "laydownKeys": ["fibers.laydown"],
}
NAMED_LIST = re.compile(r"wordList\s+(\w*Keys)\s*\{([^}]*)\}"
                        r"|checkKeys\s*\(\s*(\w+)\s*,\s*\{([^}]*)\}")
REFERENCE = os.path.join("docs", "reference.md")
TABLE_HEADINGS = ("Top-level entries", "OpenFOAM's own entries")


def source_texts(project):
    """{path: text} of every C++ file of src/openfoam."""
    texts = {}
    for root, _, files in os.walk(os.path.join(project, "src", "openfoam")):
        for name in sorted(files):
            if name.endswith((".C", ".H")):
                path = os.path.join(root, name)
                texts[os.path.relpath(path, project)] = open(path, encoding="utf-8").read()
    return texts


def accepted_entries(texts):
    """({dotted entry: where}, failures) of the code's lists of allowed keys."""
    accepted, failures, found = {}, [], set()
    for path, text in texts.items():
        for match in NAMED_LIST.finditer(text):
            name = match.group(1) or match.group(3)
            keys = LITERAL.findall(match.group(2) or match.group(4) or "")
            if name not in KEY_LISTS:
                failures.append(f"{path}: list of allowed keys '{name}' is not in KEY_LISTS of "
                                f"tests/checkDictionaryKeys.py: say which dictionary it holds")
                continue
            found.add(name)
            for dictionary in KEY_LISTS[name]:
                for key in keys:
                    accepted[f"{dictionary}.{key}" if dictionary else key] = f"{path} ({name})"
    for name in sorted(set(KEY_LISTS) - found):
        failures.append(f"list of allowed keys '{name}' (KEY_LISTS) not found in src/openfoam")
    return accepted, failures


def cells(line):
    return [cell.strip() for cell in line.strip().strip("|").split("|")]


def documented_rows(text):
    """[(dotted entry, {column: cell}, line number)] of docs/reference.md's entry tables."""
    rows, prefix, header = [], None, None
    for number, line in enumerate(text.splitlines(), 1):
        heading = re.match(r"^#{2,6}\s+(.*)", line)
        if heading:
            names = re.findall(r"`([\w.<>]+)`", heading.group(1))
            prefix = names[0] if names else ("" if heading.group(1).strip() in TABLE_HEADINGS
                                             else None)
            header = None
            continue
        if prefix is None or not line.startswith("|"):
            if not line.startswith("|"):
                header = None
            continue
        row = cells(line)
        if header is None:
            header = row
            continue
        if all(re.fullmatch(r":?-+:?", cell) for cell in row):
            continue
        columns = dict(zip(header, row))
        for key in re.findall(r"`(\w+)`", row[0]):
            rows.append((f"{prefix}.{key}" if prefix else key, columns, number))
    return rows


def literal_value(text, source):
    """The number, word or boolean a C++ argument states, else None."""
    text = text.strip()
    pointer = re.fullmatch(r"&(\w+)", text)
    if pointer:  # getCheckedScalar(dict, key, &name, ...): const scalar name = value;
        declared = re.search(r"\b" + pointer.group(1) + r"\s*=\s*([-+\d.eE]+)\s*;", source)
        return declared.group(1) if declared else None
    member = re.fullmatch(r"\w+\.(\w+)", text)
    if member:  # a settings struct's member: its initialiser in the core's headers
        declared = re.search(r"\b" + member.group(1) + r"\s*=\s*([-+\d.eE]+)\s*;", source)
        return declared.group(1) if declared else None
    word = re.fullmatch(r"\"(\w*)\"", text)
    if word:
        return word.group(1)
    if re.fullmatch(r"[-+]?\d[\d.]*(?:[eE][-+]?\d+)?|true|false", text):
        return text
    return None


ARGUMENT = r"((?:[^,(){}]|\([^()]*\))+)"
CALL = re.compile(r"\b(getChoice|getSwitch|getLabelInRange|getNonNegative|getPositive"
                  r"|getCheckedScalar)\s*\(\s*" + ARGUMENT + r",\s*\"(\w+)\"\s*"
                  r"((?:,\s*(?:\{[^}]*\}|" + ARGUMENT + r"))*)")
ARGUMENTS = re.compile(r",\s*(\{[^}]*\}|(?:[^,(){}]|\([^()]*\))+)")


def core_headers(project):
    """The text of every header of src/core (the settings structs' defaults)."""
    text = []
    for root, _, files in os.walk(os.path.join(project, "src", "core")):
        for name in sorted(files):
            if name.endswith(".hpp"):
                text.append(open(os.path.join(root, name), encoding="utf-8").read())
    return "\n".join(text)


def stated_by_code(texts, core=""):
    """[(key, what, expected, where)]: the literal defaults, choices and bounds, in the
    files that read the dictionary (those that hold a list of allowed keys or call
    checkKeys: not the readers of the restart state)."""
    stated = []
    for path, text in texts.items():
        if not NAMED_LIST.search(text) and "checkKeys(" not in text:
            continue
        for match in CALL.finditer(text):
            reader, key = match.group(1), match.group(3)
            args = [a.strip() for a in ARGUMENTS.findall(match.group(4))]
            where = f"{path}:{text.count(chr(10), 0, match.start()) + 1}"
            default = literal_value(args[0], text + "\n" + core) if args else None
            if default is not None:
                stated.append((key, "default", default, where))
            if reader == "getChoice" and len(args) > 1 and args[1].startswith("{"):
                stated.append((key, "choices", tuple(LITERAL.findall(args[1])), where))
            if reader == "getLabelInRange" and len(args) > 2:
                low, high = literal_value(args[1], text), literal_value(args[2], text)
                if low is not None and high is not None:
                    stated.append((key, "range", f"{low} to {high}", where))
    return stated


def same_value(a, b):
    try:
        return float(a) == float(b)
    except ValueError:
        return a == b


def agrees(columns, what, expected):
    allowed, default = columns.get("Allowed", ""), columns.get("Default", "")
    if what == "choices":
        return set(re.findall(r"`([^`]+)`", allowed)) == set(expected)
    if what == "range":
        return expected in allowed
    if "required" in default:
        return True  # a default the code uses only to report the missing entry
    shown = re.findall(r"`([^`]+)`", default) or [default]
    return same_value(shown[0], expected)


def check_reference(project, reference_text=None):
    """Parts 2 and 3: (passed, failures) of docs/reference.md against the code."""
    texts = source_texts(project)
    accepted, failures = accepted_entries(texts)
    if reference_text is None:
        with open(os.path.join(project, REFERENCE), encoding="utf-8") as f:
            reference_text = f.read()
    rows = documented_rows(reference_text)
    documented = {}
    for entry, _, number in rows:
        if entry in documented:
            failures.append(f"{REFERENCE}:{number}: entry '{entry}' documented twice "
                            f"(also line {documented[entry]})")
        documented.setdefault(entry, number)
    passed = 0
    for entry in sorted(accepted):
        if entry in documented:
            passed += 1
        else:
            failures.append(f"entry '{entry}', accepted by {accepted[entry]}, has no row in "
                            f"{REFERENCE}")
    for entry in sorted(set(documented) - set(accepted)):
        failures.append(f"{REFERENCE}:{documented[entry]}: entry '{entry}' is documented but "
                        f"no list of allowed keys in src/openfoam accepts it")
    for key, what, expected, where in stated_by_code(texts, core_headers(project)):
        candidates = [columns for entry, columns, _ in rows if entry.split(".")[-1] == key]
        if any(agrees(columns, what, expected) for columns in candidates):
            passed += 1
        else:
            failures.append(f"{REFERENCE}: no row of entry '{key}' gives the code's {what} "
                            f"{expected} ({where})")
    return passed, failures


def self_test(project):
    """Parts 2 and 3 catch each kind of mismatch in a changed copy of the reference."""
    with open(os.path.join(project, REFERENCE), encoding="utf-8") as f:
        text = f.read()
    cases = {
        "the reference as it is": (text, None),
        "a missing row": (re.sub(r"^\| `moveCost` .*\n", "", text, flags=re.M),
                          "'grid.moveCost', accepted by"),
        "an unknown row": (text.replace("| `seed` |", "| `seed`, `sede` |", 1),
                           "'collision.sede' is documented but"),
        "a wrong default": (re.sub(r"(\| `balanceSteps` \|[^|]*\| )`100`", r"\1`10`", text),
                            "gives the code's default 100"),
        "a wrong choice": (text.replace("`automatic`, `exact`", "`automatic`, `fast`", 1),
                           "gives the code's choices"),
    }
    failed = 0
    for name, (changed, expected) in cases.items():
        if changed == text and expected is not None:
            print(f"FAILED: {name}: the self-test could not make the change")
            failed += 1
            continue
        _, failures = check_reference(project, changed)
        ok = (not failures) if expected is None else any(expected in f for f in failures)
        print(f"{'ok' if ok else 'FAILED'}: {name}: "
              f"{'passes' if not failures else '; '.join(failures)}")
        failed += not ok
    print(f"self-test: {len(cases) - failed} of {len(cases)} cases as expected")
    return 1 if failed else 0


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--self-test":
        return self_test(sys.argv[2] if len(sys.argv) > 2 else ".")
    project = sys.argv[1] if len(sys.argv) > 1 else "."
    passed, failures = check_lists_read(project)
    documented, reference_failures = check_reference(project)
    print(f"keys read against the lists of allowed keys: {passed} passed, "
          f"{len(failures)} failed")
    print(f"{REFERENCE} against the code (entries, defaults, choices, bounds): "
          f"{documented} passed, {len(reference_failures)} failed")
    for failure in failures + reference_failures:
        print("FAILED: " + failure)
    return 1 if failures or reference_failures else 0


if __name__ == "__main__":
    sys.exit(main())
