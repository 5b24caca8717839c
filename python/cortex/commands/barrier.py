"""Membrane proteins crossing a barrier over time (thesis fig. 3.2): per snapshot the
copies of a membrane species beyond x = SPLIT (default: the membrane's mid-x), as a
fraction of their equilibrium count there, taken as half of all copies (a barrier
symmetric about SPLIT; copies on vertices at SPLIT count half). Prints per run a table
and the time the fraction first reaches 1 - 1/e; -o plots every run on one axis.

  barrier OUT                                       table and crossing time
  barrier H0 H2 H4 --labels "0 kT,2 kT,4 kT" -o barrier.png
  barrier OUT --species M --split 750 --csv barrier.csv
"""


import numpy as np

from ..errors import CortexError
from . import common

HELP = "membrane species past a barrier over time, as a fraction of equilibrium (table, PNG)"

COLUMNS = ["time_s", "fraction", "right", "total"]


def add_arguments(p):
    common.add_runs_over_time(p, "PNG to write (no plot without it)")
    common.add_membrane(p)
    p.add_argument("--species", help="membrane species (default: the membrane's only one)")
    p.add_argument("--split", type=common.finite_float, help="x (nm) past which copies count (default: the membrane's mid-x)")


def table(outdir, membrane_name, species_name, split):
    run = common.open_run(outdir)
    membrane = common.membranes_of(run.snapshot(0), membrane_name)[0]
    species = common.species_of(membrane, species_name, run.trajectory_path)
    x = membrane.vertices[:, 0]
    if split is None:
        split = 0.5 * (x.min() + x.max())
    rows = []
    for s in run.snapshots():
        m = s.membranes.get(membrane.name)
        if m is None:
            continue
        copies = m.species[species]
        tol = 1e-6 * (1.0 + abs(split))
        weight = np.where(m.vertices[:, 0] > split + tol, 1.0, np.where(m.vertices[:, 0] >= split - tol, 0.5, 0.0))
        right = float(np.sum(weight * copies))
        total = float(np.sum(copies))
        rows.append([s.time, right / (0.5 * total) if total > 0 else np.nan, right, total])
    return np.array(rows, dtype=float), membrane.name, species, split


def crossing_time(rows, level=1.0 - np.exp(-1.0)):
    """s: the first snapshot time at which the fraction reaches `level` (nan if never)."""
    reached = np.nonzero(rows[:, 1] >= level)[0]
    return float(rows[reached[0], 0]) if len(reached) else float("nan")


def run(args):
    labels = common.run_labels(args)
    tables = []
    for label, outdir in zip(labels, args.outdir):
        rows, name, species, split = table(outdir, args.membrane, args.species, args.split)
        tables.append(rows)
        common.print_rows(f"{label}: membrane '{name}', species '{species}', past x = {split:g} nm",
                          [("t (s)", "8.3f"), ("fraction", "9.3f"), ("right", "9.0f"), ("total", "9.0f")], rows)
        t_e = crossing_time(rows)
        print(f"{label}: fraction {rows[-1, 1]:.3f} at t = {rows[-1, 0]:g} s; reaches 1 - 1/e at "
              + (f"t = {t_e:g} s" if np.isfinite(t_e) else "no snapshot"))
    if args.csv:
        common.write_tables_csv(args.csv, COLUMNS, labels, tables)
    if args.out:
        def decorate(ax):
            ax.axhline(1.0, color="0.6", lw=0.8, ls="--")
            ax.set_ylim(0.0, 1.1)

        common.plot_over_time(args, labels, tables, "past the barrier / equilibrium", decorate)
    return 0
