"""The fibers' dispersion seen in the written fibers: the centre of every fiber at
every write time after its first, its displacement across the fibers' mean drift
(the mean of all these displacements' directions) from where it was first written,
against the distance it has travelled along the drift since. In laminar air fibers
injected alike travel on one line; in turbulent air their paths spread with the
distance travelled."""
import math

import numpy as np


def displacements(centres, planar):
    """[(along, across)] of every fiber at every write time after its first; across is
    signed in a 2D case (planar: the in-plane axis normal to the drift), else its size."""
    steps = [centre - track[0][1] for track in centres.values() if len(track) > 1 for _, centre in track[1:]]
    if not steps:
        return []
    drift = sum(d / np.linalg.norm(d) for d in steps if np.linalg.norm(d) > 0)
    if np.linalg.norm(drift) == 0:
        return []
    drift = drift / np.linalg.norm(drift)
    across_axis = np.array([-drift[1], drift[0], 0.0])
    result = []
    for d in steps:
        along = float(d @ drift)
        if planar and np.linalg.norm(across_axis) > 0:
            across = float(d @ across_axis / np.linalg.norm(across_axis))
        else:
            across = float(np.linalg.norm(d - along * drift))
        result.append((along, across))
    return result


def rms_beyond(points, fraction=0.5):
    """The rms displacement across of the positions that travelled more than fraction
    of the longest distance; (rms, count, threshold) or None."""
    if not points:
        return None
    threshold = fraction * max(f for f, _ in points)
    far = [a for f, a in points if f > threshold]
    if not far or threshold <= 0:
        return None
    return math.sqrt(sum(a * a for a in far) / len(far)), len(far), threshold
