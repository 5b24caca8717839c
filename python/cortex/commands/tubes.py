"""Tubes pulled out of a vesicle by a filament bundle (thesis fig. 2.4b). Per snapshot,
along the axis of the filaments (the principal axis of their beads; the bundle may turn
with the vesicle) through the centroid of the enclosed volume: the body's radius at the
equator and, at each pole, the protrusion's length beyond the body and its median
radius over the middle third of that length. A tube is a protrusion much narrower than
the body; a vesicle merely stretched into a prolate shape has protrusions as wide as
itself. The force on each pole: the magnitude of the summed membrane contact forces
on the beads on that side of the vesicle's centre (nan in runs written without contact
forces). With a `tension` γ and `bending_modulus` κ in the membrane's config, the
radius and force of a tube at that tension, √(κ/2γ) and 2π√(2κγ), are printed beside;
those are for a tube drawn from a flat membrane. A tube drawn from a vesicle whose
volume is held takes its volume from the body against the body's pressure Δp (the
`pressure` observable), so per length it costs πκ/r + 2πγr − πΔp r²: least at
κ/r² = 2γ − 2Δp r, and its force is that cost per length there. These are printed too,
with the last snapshot's Δp.

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

COLUMNS = ["time_s", "body_radius_nm", "plus_length_nm", "plus_radius_nm", "minus_length_nm", "minus_radius_nm",
           "plus_force_pN", "minus_force_pN"]


def add_arguments(p):
    common.add_runs_over_time(p, "PNG of the tube lengths to write (no plot without it)")
    common.add_membrane(p)


def bundle_axis(filaments, where):
    """Unit principal axis of the beads of the filaments (a bundle's axis)."""
    if filaments is None or len(filaments) == 0:
        raise CortexError(f"{where} has no filaments to give the axis")
    beads = np.concatenate(filaments.polylines)
    return np.linalg.eigh(np.cov((beads - beads.mean(axis=0)).T))[1][:, -1]


def pole(vertices, along, across, body_radius):
    """(length beyond the body, median radius over its middle third) of the protrusion at
    the pole where `along` is largest; the radius is nan when fewer than 3 vertices lie
    in that third. The radius is measured about the middle third's own axis (through its
    vertices' centroid, along their principal axis when that third is longer than twice
    as wide), so a tube that has bent or drifted off the bundle's line is not measured
    as wider than it is."""
    length = float(along.max() - body_radius)
    middle = (along > body_radius + length / 3) & (along < body_radius + 2 * length / 3)
    if length <= 0 or middle.sum() < 3:
        return length, math.nan
    radius = float(np.median(across[middle]))
    if length / 3 > 4 * radius:
        tube = vertices[middle] - vertices[middle].mean(axis=0)
        axis = np.linalg.eigh(np.cov(tube.T))[1][:, -1]
        radius = float(np.median(np.linalg.norm(tube - np.outer(tube @ axis, axis), axis=1)))
    return length, radius


def shape(membrane, axis, centre=None):
    """[body radius, + pole length, + pole radius, − pole length, − pole radius], nm, about
    `centre` (default: the centroid of the enclosed volume)."""
    if centre is None:
        _, centre = geometry.volume_centroid(membrane.vertices, membrane.triangles)
    along = (membrane.vertices - centre) @ axis
    across = np.linalg.norm(membrane.vertices - centre - np.outer(along, axis), axis=1)
    # The body's radius: at the vertices nearest the equatorial plane (1%, at least 8).
    equator = np.argsort(np.abs(along))[:max(8, len(along) // 100)]
    body = float(np.median(across[equator]))
    return [body, *pole(membrane.vertices, along, across, body), *pole(membrane.vertices, -along, across, body)]


def pole_forces(filaments, centre, axis):
    """[|force on the + pole|, |force on the − pole|], pN: the membrane's contact forces
    summed over the beads on each side of `centre` along `axis`."""
    if getattr(filaments, "contact_force", None) is None:
        return [math.nan, math.nan]
    plus = (filaments.beads - centre) @ axis > 0
    force = filaments.contact_force
    return [float(np.linalg.norm(force[plus].sum(axis=0))), float(np.linalg.norm(force[~plus].sum(axis=0)))]


def measure(membrane, filaments, where):
    """One row after the time: shape() along the bundle's axis, then pole_forces()."""
    axis = bundle_axis(filaments, where)
    _, centre = geometry.volume_centroid(membrane.vertices, membrane.triangles)
    return [*shape(membrane, axis, centre), *pole_forces(filaments, centre, axis)]


def tube_of_config(run, name):
    """(√(κ/2γ) nm, 2π√(2κγ) pN, κ, γ) of membrane `name` from the stored config, or None
    without a constant tension (none, or a schedule)."""
    if run.config is None:
        return None
    for m in tomllib.loads(run.config).get("membrane", []):
        tension, kappa = m.get("tension", 0.0), m.get("bending_modulus", 100.0)
        if m.get("name") == name and isinstance(tension, float) and tension > 0 and isinstance(kappa, float):
            return math.sqrt(kappa / (2 * tension)), 2 * math.pi * math.sqrt(2 * kappa * tension), kappa, tension
    return None


def tube_with_pressure(kappa, tension, pressure):
    """(radius nm, force pN) of a long tube at bending modulus κ, tension γ and body
    pressure Δp: the least of e(r) = πκ/r + 2πγr − πΔp r², the smallest positive root of
    2Δp r³ − 2γ r² + κ = 0, and e there. None when e has no minimum (Δp too high for
    the tension to hold a tube: Δp ≥ (2γ)^{3/2} / √(27κ))."""
    roots = np.roots([2 * pressure, -2 * tension, 0.0, kappa])  # a quadratic when Δp = 0
    radii = sorted(r.real for r in roots if abs(r.imag) < 1e-9 * abs(r) and r.real > 0)
    if not radii:
        return None
    r = radii[0]
    return r, math.pi * kappa / r + 2 * math.pi * tension * r - math.pi * pressure * r * r


def table(outdir, membrane_name):
    run = common.open_run(outdir)
    membrane = common.closed_membrane(run, membrane_name)
    rows = []
    for s in run.snapshots():
        m = s.membranes.get(membrane.name)
        if m is not None:
            rows.append([s.time, *measure(m, s.filaments, f"{run.trajectory_path}: snapshot {s.name}")])
    expected = tube_of_config(run, membrane.name)
    if expected is not None:
        column = f"membranes.{membrane.name}.pressure"
        pressure = run.observables[column][-1] if column in run.observables else math.nan
        tube = tube_with_pressure(*expected[2:], pressure) if math.isfinite(pressure) else None
        expected = (*expected[:2], pressure, *(tube or (math.nan, math.nan)))
    return np.array(rows, dtype=float), membrane.name, expected


def run(args):
    labels = common.run_labels(args)
    tables = []
    for label, outdir in zip(labels, args.outdir):
        rows, name, expected = table(outdir, args.membrane)
        tables.append(rows)
        common.print_rows(f"{label}: membrane '{name}'",
                          [("t (s)", "8.3f"), ("body r (nm)", "12.1f"), ("+ length", "9.1f"), ("+ radius", "9.1f"),
                           ("- length", "9.1f"), ("- radius", "9.1f"), ("+ force", "8.2f"), ("- force", "8.2f")],
                          rows)
        last = rows[-1]
        radius_at = f" (√(κ/2γ) = {expected[0]:.1f} nm)" if expected else ""
        force_at = f" (2π√(2κγ) = {expected[1]:.2f} pN)" if expected else ""
        print(f"{label}: at t = {last[0]:g} s tubes {last[2]:.0f} and {last[4]:.0f} nm long, radii {last[3]:.1f} "
              f"and {last[5]:.1f} nm{radius_at}, forces on the poles {last[6]:.2f} and {last[7]:.2f} pN{force_at}, "
              f"body radius {last[1]:.0f} nm")
        if expected and math.isfinite(expected[3]):
            print(f"{label}: with the body's pressure Δp = {expected[2]:.3g} pN/nm² at t = {last[0]:g} s a tube "
                  f"drawn from it has radius {expected[3]:.1f} nm and force {expected[4]:.2f} pN")
    if args.csv:
        common.write_tables_csv(args.csv, COLUMNS, labels, tables)
    if args.out:
        # Both poles' lengths: the plot helper draws column 1, so each pole is a table of its own.
        poles = [rows[:, [0, k]] for rows in tables for k in (2, 4)]
        names = [f"{label} {end}" for label in labels for end in ("+ pole", "- pole")]
        common.plot_over_time(args, names, poles, "tube length beyond the body (nm)")
    return 0
