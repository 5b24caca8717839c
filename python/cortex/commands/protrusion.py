"""Membrane protrusion by filaments over time (thesis fig. 2.5): per snapshot the
membrane's largest height above its initial mid-plane, measured along that plane's
normal turned along the filaments' mean growth direction, the farthest filament tip along the same
axis, and the total filament length. Prints per run a table and the growth rate, the
least-squares slope of the height over the second half of the run; -o plots the height
of every run on one axis.

  protrusion OUT                                        table and rate
  protrusion N4 N7 N10 --labels "N=4,N=7,N=10" -o height.png
  protrusion OUT --membrane patch --csv height.csv
"""


import numpy as np

from ..errors import CortexError
from . import common

HELP = "membrane height pushed out by filaments over time, and its growth rate (table, PNG)"

COLUMNS = ["time_s", "height_nm", "tip_nm", "filament_length_nm"]


def add_arguments(p):
    common.add_runs_over_time(p, "PNG to write (no plot without it)")
    common.add_membrane(p)


def axis_of(vertices, growth):
    """Centre and unit normal of the best-fit plane of the vertices, the normal turned
    along the filaments' mean growth direction (towards their plus ends)."""
    centre = vertices.mean(axis=0)
    normal = np.linalg.svd(vertices - centre, full_matrices=False)[2][-1]
    if np.dot(growth, normal) < 0:
        normal = -normal
    return centre, normal


def table(outdir, membrane_name):
    run = common.open_run(outdir)
    first = run.snapshot(0)
    membrane = common.membranes_of(first, membrane_name)[0]
    filaments = first.filaments
    if filaments is None or len(filaments) == 0:
        raise CortexError(f"{run.trajectory_path}: the first snapshot has no filaments")
    growth = sum(line[-1] - line[-2] for line in filaments.polylines if len(line) > 1)
    centre, normal = axis_of(membrane.vertices, growth)
    rows = []
    for s in run.snapshots():
        m = s.membranes.get(membrane.name)
        f = s.filaments
        if m is None or f is None:
            continue
        tips = np.array([line[-1] for line in f.polylines]) if len(f) else np.zeros((0, 3))
        height = float(np.max((m.vertices - centre) @ normal))
        tip = float(np.max((tips - centre) @ normal)) if len(tips) else np.nan
        rows.append([s.time, height, tip, float(np.sum(f.lengths))])
    return np.array(rows, dtype=float), membrane.name


def growth_rate(rows):
    """nm/s: the slope of height(t) over the second half of the run (nan with < 3 points)."""
    half = rows[rows[:, 0] >= 0.5 * (rows[0, 0] + rows[-1, 0])]
    if len(half) < 3:
        return float("nan")
    return float(np.polyfit(half[:, 0], half[:, 1], 1)[0])


def run(args):
    labels = common.run_labels(args)
    tables = []
    for label, outdir in zip(labels, args.outdir):
        rows, name = table(outdir, args.membrane)
        tables.append(rows)
        common.print_rows(f"{label}: membrane '{name}'",
                          [("t (s)", "8.3f"), ("height (nm)", "12.1f"), ("tip (nm)", "9.1f"), ("length (nm)", "12.0f")],
                          rows)
        print(f"{label}: height {rows[0, 1]:.1f} -> {rows[-1, 1]:.1f} nm, growth rate over the second half "
              f"{growth_rate(rows):.1f} nm/s")
    if args.csv:
        common.write_tables_csv(args.csv, COLUMNS, labels, tables)
    if args.out:
        common.plot_over_time(args, labels, tables, "largest membrane height (nm)")
    return 0
