"""Columns found by their names' pattern, for the columns other features add.

Assumed names (detected, not fixed; a column that is missing is not reported):
- evaporated binder: a name starting with 'evaporated' or 'phaseChange' (mass lost by
  the parcels to phase change);
- per liquid species: 'captured<Species>' or 'evaporated<Species>' with an optional
  'Total'/'Step'/'Mass' before or after the species and an optional '_' between
  (capturedTotalH2O, captured_H2O, evaporatedH2OTotal, ...);
- a running total where the name says 'Total' or neither; a per-step column ('Step')
  is summed over the rows when there is no total of the same species.
- load imbalance (parallelStatistics.dat): any name containing 'imbalance'.
"""
import re

EVAPORATED = r"evaporated|phaseChange"
CAPTURED = r"captured"


def _parse(name, prefix):
    m = re.match(r"^(?:%s)(Total|Step|Mass)?_?([A-Za-z0-9]*?)_?(Total|Step|Mass)?$" % prefix, name)
    if not m:
        return None
    step = "Step" in (m.group(1), m.group(3))
    return m.group(2), step


def species_totals(table, prefix):
    """{species ('' for the whole): (total at the last row, column name, summed?)}."""
    totals, steps = {}, {}
    for name in table.names:
        parsed = _parse(name, prefix)
        if parsed is None:
            continue
        species, step = parsed
        (steps if step else totals).setdefault(species, name)
    result = {}
    for species, name in totals.items():
        result[species] = (table.last()[name], name, False)
    for species, name in steps.items():
        if species not in result:
            result[species] = (sum(table.column(name)), name, True)
    return result


def imbalance_columns(table):
    return [n for n in table.names if "imbalance" in n.lower()] if table else []


def wall_time_columns(table):
    return [n for n in table.names if n.startswith("wallTime")]
