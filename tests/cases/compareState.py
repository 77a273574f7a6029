"""Compare two dropletFiber restart-state files (fibers, injector counters,
totals, averaging window) entry by entry.

Usage: compareState.py A B REL_TOL [--only KEY,KEY]

Both files must have the same structure (same fibers, same entries, same list
lengths; with --only, among the entries compared). The numbers of an entry agree when they differ by at most REL_TOL
times the largest magnitude in that entry (so that a velocity component that
is round-off around zero is judged against the entry's scale).
Prints `N passed, N failed`.
"""
import re
import sys

TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_.:]*|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[{}();]")


def entries(path):
    """[(dotted key, [numbers], [words])] in file order."""
    text = re.sub(r"//[^\n]*", "", open(path).read())
    # OpenFOAM writes a list of equal values as N { value }: expand it
    text = re.sub(r"(\d+)\s*\{\s*([^{}\s]+)\s*\}",
                  lambda m: "(" + " ".join([m.group(2)] * int(m.group(1))) + ")", text)
    toks = TOKEN.findall(text)
    out, scope, i = [], [], 0
    while i < len(toks):
        t = toks[i]
        if t == "}":
            scope.pop()
            i += 1
            continue
        if i + 1 < len(toks) and toks[i + 1] == "{":
            scope.append(t)
            i += 2
            continue
        key, nums, words = ".".join(scope + [t]), [], []
        i += 1
        while i < len(toks) and toks[i] != ";":
            tok = toks[i]
            if tok not in "()":
                try:
                    nums.append(float(tok))
                except ValueError:
                    words.append(tok)
            i += 1
        i += 1
        out.append((key, nums, words))
    return out


a, b, tol = entries(sys.argv[1]), entries(sys.argv[2]), float(sys.argv[3])
only = sys.argv[5].split(",") if len(sys.argv) > 5 and sys.argv[4] == "--only" else None
if only:
    # The entries compared only (a parallel run's state also names its grid block)
    a = [e for e in a if any(e[0].startswith(o) or ("." + o) in e[0] for o in only)]
    b = [e for e in b if any(e[0].startswith(o) or ("." + o) in e[0] for o in only)]
passed = failed = 0
worst = 0.0
if [k for k, _, _ in a] != [k for k, _, _ in b]:
    print("FAILED: different entries:", set(k for k, _, _ in a) ^ set(k for k, _, _ in b))
    failed += 1
for (ka, na, wa), (kb, nb, wb) in zip(a, b):
    if only and not any(ka.startswith(o) or ("." + o) in ka for o in only):
        continue
    if ka in ("time",) or ka.endswith("timeIndex"):
        continue
    if wa != wb or len(na) != len(nb):
        failed += 1
        print("FAILED: %s: structure differs (%d vs %d numbers)" % (ka, len(na), len(nb)))
        continue
    scale = max([abs(v) for v in na + nb] + [1e-300])
    diff = max([abs(x - y) for x, y in zip(na, nb)] + [0.0]) / scale
    worst = max(worst, diff)
    if diff <= tol:
        passed += 1
    else:
        failed += 1
        print("FAILED: %s differs by %.3g relative (tolerance %g)" % (ka, diff, tol))
print("largest relative difference: %.3g" % worst)
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
