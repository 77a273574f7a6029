"""The fibers' turbulent dispersion seen in the written fibers: the centre of every
fiber at every write time, its displacement across gravity from where it was first
written, against the distance it has fallen since. In laminar air a fiber falls
straight (displacements of the order of the flow's own drift); in turbulent air the
displacements spread with the fall."""
import math
import os
import re

import numpy as np


def gravity(case):
    """The unit vector of constant/g, or -y when it cannot be read."""
    path = os.path.join(case, "constant", "g")
    try:
        m = re.search(r"value\s*\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)", open(path).read())
        g = np.array([float(v) for v in m.groups()])
        if np.linalg.norm(g) > 0:
            return g / np.linalg.norm(g)
    except (OSError, AttributeError, ValueError):
        pass
    return np.array([0.0, -1.0, 0.0])


def displacements(case, centres, planar):
    """[(fall, across)] of every fiber at every write time after its first; across is
    signed in a 2D case (planar: the in-plane axis normal to gravity), else its size."""
    g = gravity(case)
    across_axis = np.array([-g[1], g[0], 0.0])
    result = []
    for track in centres.values():
        if len(track) < 2:
            continue
        start = track[0][1]
        for _, centre in track[1:]:
            d = centre - start
            fall = float(d @ g)
            lateral = d - fall * g
            across = float(d @ across_axis) if planar and np.linalg.norm(across_axis) > 0 \
                else float(np.linalg.norm(lateral))
            result.append((fall, across))
    return result


def rms_beyond(points, fraction=0.5):
    """The rms displacement across of the positions that fell more than fraction of
    the largest fall; (rms, count, threshold) or None."""
    if not points:
        return None
    threshold = fraction * max(f for f, _ in points)
    far = [a for f, a in points if f > threshold]
    if not far or threshold <= 0:
        return None
    return math.sqrt(sum(a * a for a in far) / len(far)), len(far), threshold
