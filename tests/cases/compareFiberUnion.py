"""The fibers of a parallel run, held one processor each, against a serial run's.

Usage: compareFiberUnion.py SERIAL_STATE PARALLEL_CASE STATE_PATH REL_TOL

Reads STATE_PATH (e.g. 0.2/uniform/dropletFiber/dropletFiber) of every
processor directory of PARALLEL_CASE and checks that
  - each state names how many processors wrote it and which one;
  - no fiber (fiber<id>) is held by two processors;
  - the union of their fibers, sorted by id, with processor 0's injector
    counters and totals, equals SERIAL_STATE to REL_TOL (compareState.py,
    entries fibers, injectors, totals).
Prints the fibers each processor holds; exit 1 on a failure.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
serial, case, state_path, tol = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]


def top_level(text):
    """[(key, start, end)] of the top-level entries of an OpenFOAM dictionary text."""
    text = re.sub(r"//[^\n]*", lambda m: " " * len(m.group(0)), text)
    out, i, n = [], 0, len(text)
    while i < n:
        m = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)").match(text, i)
        if not m:
            break
        key, j, depth = m.group(1), m.end(), 0
        while j < n:
            c = text[j]
            depth += c in "({"
            depth -= c in ")}"
            j += 1
            if depth == 0 and (c == ";" or c == "}"):
                break
        out.append((key, m.start(1), j))
        i = j
    return out


def fiber_blocks(text):
    """{id: block text} of the entries of the top-level dictionary 'fibers'."""
    for key, start, end in top_level(text):
        if key == "fibers":
            body = text[text.index("{", start) + 1:end - 1]
            return {int(k[5:]): body[s:e] for k, s, e in top_level(body)}
    raise SystemExit("FAILED: no entry 'fibers'")


procs = sorted(glob.glob(os.path.join(case, "processor[0-9]*")), key=lambda p: int(p.split("processor")[-1]))
failed = 0
union = {}
texts = []
for p in procs:
    text = open(os.path.join(p, state_path)).read()
    texts.append(text)
    rank = int(p.split("processor")[-1])
    written = dict((k, text[s:e]) for k, s, e in top_level(text))
    if not re.search(r"processors\s+%d;" % len(procs), written.get("processors", "")) or \
            not re.search(r"processor\s+%d;" % rank, written.get("processor", "")):
        print("FAILED: %s does not say it was written by processor %d of %d" % (p, rank, len(procs)))
        failed += 1
    fibers = fiber_blocks(text)
    print("processor%d holds fibers %s" % (rank, sorted(fibers)))
    for fid, block in fibers.items():
        if fid in union:
            print("FAILED: fiber%d held by two processors" % fid)
            failed += 1
        union[fid] = block

# processor 0's state with the union of the fibers, in id order (a serial run's order)
text = texts[0]
merged, last = [], 0
for key, start, end in top_level(text):
    if key in ("processors", "processor"):
        merged.append(text[last:start])
        last = end
    elif key == "fibers":
        merged.append(text[last:start])
        merged.append("fibers\n{\n" + "\n".join(union[f] for f in sorted(union)) + "\n}")
        last = end
merged.append(text[last:])
with tempfile.NamedTemporaryFile("w", suffix=".state", delete=False) as f:
    f.write("".join(merged))
    merged_path = f.name
status = subprocess.call([sys.executable, os.path.join(here, "compareState.py"), serial, merged_path, tol,
                          "--only", "fibers,injectors,totals"])
os.unlink(merged_path)
print("%d fibers on %d processors; union %s the serial run's" % (len(union), len(procs),
                                                                 "equals" if status == 0 else "DIFFERS from"))
sys.exit(1 if failed or status else 0)
