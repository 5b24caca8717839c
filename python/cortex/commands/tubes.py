"""Tubes pulled out of a vesicle by a filament bundle (thesis fig. 2.4b). Per snapshot,
along the axis of the filaments (the principal axis of their beads; the bundle may turn
with the vesicle) through the centroid of the enclosed volume: the body's radius at the
equator and, at each pole, the protrusion's length beyond the body and its median
radius over the middle third of that length. A tube is a protrusion much narrower than
the body; a vesicle merely stretched into a prolate shape has protrusions as wide as
itself. With a `tension` γ and `bending_modulus` κ in the membrane's config, the radius
of a tube at that tension, √(κ/2γ), is printed beside.

  tubes OUT                                  table
  tubes OUT -o tubes.png --csv tubes.csv     plot the tube lengths, write the table
"""

import math
import tomllib

import numpy as np

from .. import geometry
from ..errors import CortexError
from . import common

HELP = "tubes pulled out of a vesicle's poles by filaments: length and radius over time (table, PNG)"

COLUMNS = ["time_s", "body_radius_nm", "plus_length_nm", "plus_radius_nm", "minus_length_nm", "minus_radius_nm"]


def add_arguments(p):
    common.add_runs_over_time(p, "PNG of the tube lengths to write (no plot without it)")
    common.add_membrane(p)


def bundle_axis(filaments, where):
    """Unit principal axis of the beads of the filaments (a bundle's axis)."""
    if filaments is None or len(filaments) == 0:
        raise CortexError(f"{where} has no filaments to give the axis")
    beads = np.concatenate(filaments.polylines)
    return np.linalg.eigh(np.cov((beads - beads.mean(axis=0)).T))[1][:, -1]


def pole(along, across, body_radius):
    """(length beyond the body, median radius over its middle third) of the protrusion at
    the pole where `along` is largest; the radius is nan when fewer than 3 vertices lie
    in that third."""
    length = float(along.max() - body_radius)
    middle = (along > body_radius + length / 3) & (along < body_radius + 2 * length / 3)
    radius = float(np.median(across[middle])) if length > 0 and middle.sum() >= 3 else math.nan
    return length, radius


def shape(membrane, axis):
    """[body radius, + pole length, + pole radius, − pole length, − pole radius], nm."""
    _, centre = geometry.volume_centroid(membrane.vertices, membrane.triangles)
    along = (membrane.vertices - centre) @ axis
    across = np.linalg.norm(membrane.vertices - centre - np.outer(along, axis), axis=1)
    # The body's radius: at the vertices nearest the equatorial plane (1%, at least 8).
    equator = np.argsort(np.abs(along))[:max(8, len(along) // 100)]
    body = float(np.median(across[equator]))
    return [body, *pole(along, across, body), *pole(-along, across, body)]


def tube_radius_of_config(run, name):
    """√(κ/2γ) of membrane `name` from the stored config, or None without a constant
    tension (none, or a schedule)."""
    if run.config is None:
        return None
    for m in tomllib.loads(run.config).get("membrane", []):
        tension, kappa = m.get("tension", 0.0), m.get("bending_modulus", 100.0)
        if m.get("name") == name and isinstance(tension, float) and tension > 0 and isinstance(kappa, float):
            return math.sqrt(kappa / (2 * tension))
    return None


def table(outdir, membrane_name):
    run = common.open_run(outdir)
    membrane = common.closed_membrane(run, membrane_name)
    rows = []
    for s in run.snapshots():
        m = s.membranes.get(membrane.name)
        if m is not None:
            rows.append([s.time, *shape(m, bundle_axis(s.filaments, f"{run.trajectory_path}: snapshot {s.name}"))])
    return np.array(rows, dtype=float), membrane.name, tube_radius_of_config(run, membrane.name)


def run(args):
    labels = common.run_labels(args)
    tables = []
    for label, outdir in zip(labels, args.outdir):
        rows, name, expected = table(outdir, args.membrane)
        tables.append(rows)
        common.print_rows(f"{label}: membrane '{name}'",
                          [("t (s)", "8.3f"), ("body r (nm)", "12.1f"), ("+ length", "9.1f"), ("+ radius", "9.1f"),
                           ("- length", "9.1f"), ("- radius", "9.1f")], rows)
        last = rows[-1]
        at = f" (√(κ/2γ) = {expected:.1f} nm)" if expected else ""
        print(f"{label}: at t = {last[0]:g} s tubes {last[2]:.0f} and {last[4]:.0f} nm long, radii {last[3]:.1f} "
              f"and {last[5]:.1f} nm{at}, body radius {last[1]:.0f} nm")
    if args.csv:
        common.write_tables_csv(args.csv, COLUMNS, labels, tables)
    if args.out:
        # Both poles' lengths: the plot helper draws column 1, so each pole is a table of its own.
        poles = [rows[:, [0, k]] for rows in tables for k in (2, 4)]
        names = [f"{label} {end}" for label in labels for end in ("+ pole", "- pole")]
        common.plot_over_time(args, names, poles, "tube length beyond the body (nm)")
    return 0
