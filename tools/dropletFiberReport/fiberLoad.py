"""How the mass sits along the fibers at one time: sigma (fiber mass per length) over
the fiber length, and the captured binder per length.

Each segment stands for its length with sigma the mean of its two end points (the
trapezoidal rule: the sum of sigma times length is the fibers' mass, as the table's
fiberMass), and for its captured binder per length its cell value
segmentCapturedMass over its length. Weighted fibers (point array `represents`, docs/model.md
sec. 9): each segment stands for its length times the physical fibers its fiber represents.
"""
import numpy as np


def _weighted(values, weights):
    total = weights.sum()
    mean = float((values * weights).sum() / total)
    spread = float(np.sqrt(((values - mean) ** 2 * weights).sum() / total))
    return mean, spread / mean if mean else float("nan")


def fiber_load(fibers):
    """Totals, length-weighted statistics and the sigma histogram (bins, lengths);
    None without segments or without sigma."""
    if fibers is None or len(fibers.segments) == 0 or "sigma" not in fibers.point_data:
        return None
    segmentLengths = fibers.segment_lengths()
    lengths = segmentLengths  # the physical fibers' length each segment stands for
    if "represents" in fibers.point_data:
        lengths = segmentLengths * fibers.segment_mean("represents")
    sigma = fibers.segment_mean("sigma")
    load = {"time": fibers.time, "segments": len(lengths), "length": float(lengths.sum()),
            "mass": float((sigma * lengths).sum()), "sigmaMin": float(sigma.min()),
            "sigmaMax": float(sigma.max())}
    if "fiberId" in fibers.point_data:
        load["fibers"] = len(np.unique(fibers.point_data["fiberId"]))
    load["sigmaMean"], load["sigmaCoV"] = _weighted(sigma, lengths)
    low, high = load["sigmaMin"], load["sigmaMax"]
    edges = np.linspace(low, high if high > low else low * (1 + 1e-9) + 1e-300, 31)
    load["histogram"] = np.histogram(sigma, bins=edges, weights=lengths)
    if "segmentCapturedMass" in fibers.cell_data:
        binder = fibers.cell_data["segmentCapturedMass"] / segmentLengths
        load["binderMean"], load["binderCoV"] = _weighted(binder, lengths)
        load["bareFraction"] = float(lengths[binder <= 0].sum() / lengths.sum())
        load["binderHistogram"] = np.histogram(binder, bins=30, weights=lengths)
    return load
