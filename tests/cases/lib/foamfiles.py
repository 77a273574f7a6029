"""Readers for the OpenFOAM files the case tests check, written independently of
OpenFOAM and of dropletFiber (plain Python, standard library only).

- read_field(path): an ASCII IOField / List of scalars or vectors, in either the
  uniform form `N{value}` or the list form `N ( ... )`.
- read_table(path): a postProcessing .dat table (comment lines start with '#',
  the last comment line holds the column names) as a list of dicts.
- cloud_totals(case, time, cloud): parcel count, droplet count and droplet mass
  of a cloud as OpenFOAM wrote it at a time, summed over processor folders.
- cloud_species_mass(case, time, cloud, species): the droplet mass of one liquid
  species of a reacting or spray cloud as OpenFOAM wrote it at a time.
"""
import math
import os
import re

_HEADER_END = re.compile(r"FoamFile\s*\{.*?\}", re.S)


def _strip(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    return _HEADER_END.sub(" ", text, count=1)


def _value(token):
    token = token.strip()
    if token.startswith("("):
        return tuple(float(v) for v in token.strip("()").split())
    return float(token)


def read_field(path):
    body = _strip(open(path).read()).strip()
    m = re.match(r"(\d+)\s*\{(.*)\}", body, re.S)
    if m:
        return [_value(m.group(2))] * int(m.group(1))
    m = re.match(r"(\d+)\s*\((.*)\)\s*$", body, re.S)
    if not m:
        if re.match(r"0\s*$", body) or body == "":
            return []
        raise ValueError("cannot parse list in %s" % path)
    n, inner = int(m.group(1)), m.group(2)
    if "(" in inner:
        values = [_value(t) for t in re.findall(r"\([^()]*\)", inner)]
    else:
        values = [float(t) for t in inner.split()]
    if len(values) != n:
        raise ValueError("%s: %d values, header says %d" % (path, len(values), n))
    return values


def read_table(path):
    names, rows = None, []
    for line in open(path):
        if line.startswith("#"):
            names = [c.strip() for c in line[1:].split("\t") if c.strip()]
            continue
        if not line.strip():
            continue
        values = [float(v) for v in line.split()]
        rows.append(dict(zip(names, values)))
    return rows


def _cloud_folders(case, time, cloud):
    """Each folder holding `cloud` written at `time`, over the case or its
    processor* folders, with its parcels' d, nParticle and rho."""
    roots = sorted(
        os.path.join(case, d) for d in os.listdir(case) if d.startswith("processor")
    ) or [case]
    for root in roots:
        cdir = os.path.join(root, time, "lagrangian", cloud)
        if os.path.isdir(cdir):
            yield cdir, [read_field(os.path.join(cdir, name))
                         for name in ("d", "nParticle", "rho")]


def cloud_totals(case, time, cloud):
    """(parcels, droplets, mass) of `cloud` written at `time` (a directory
    name), over the case or its processor* folders."""
    parcels, droplets, mass = 0, 0.0, 0.0
    for _, (d, n, rho) in _cloud_folders(case, time, cloud):
        parcels += len(d)
        droplets += sum(n)
        mass += sum(ni * ri * math.pi / 6.0 * di ** 3 for di, ni, ri in zip(d, n, rho))
    return parcels, droplets, mass


def cloud_species_mass(case, time, cloud, species):
    """Droplet mass of one species in `cloud` written at `time`: the sum over
    parcels of nParticle rho pi d^3/6 times the parcel's mass fraction of the
    species (field Y<species>(l) or Y<species>), over the case or its
    processor* folders."""
    mass = 0.0
    for cdir, (d, n, rho) in _cloud_folders(case, time, cloud):
        # Y<species> followed by the phase's state label: (l) for a liquid
        names = [n for n in ("Y" + species + "(l)", "Y" + species)
                 if os.path.exists(os.path.join(cdir, n))]
        if not names:
            raise ValueError("%s: no field Y%s(l) or Y%s" % (cdir, species, species))
        y = read_field(os.path.join(cdir, names[0]))
        mass += sum(ni * ri * math.pi / 6.0 * di ** 3 * yi
                    for di, ni, ri, yi in zip(d, n, rho, y))
    return mass
