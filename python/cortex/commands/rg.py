"""Radius of gyration of the filament beads over time, one table row per snapshot.

Rg(t) = sqrt(mean_i |r_i - r_mean|^2) over the beads of the selected filaments (every
bead counts once; with 40-monomer cylinders the beads are ~108 nm apart, so this is the
length-weighted Rg up to the half cylinders at the ends); --per-length weights the
cylinders' midpoints by their lengths instead. Prints per run a table (time, Rg,
Rg/Rg(0), filaments, beads, bound linkers, motors, branch points) and the relative
change; -o plots Rg(t) of every run on one axis (--bound adds the bound counts).

  rg OUT                                   table only
  rg OUT1 OUT2 --labels "seed 1,seed 2" --bound -o rg.png
  rg OUT --normalize --type 0 --csv rg.csv
"""


import numpy as np

from .. import geometry, plotting
from ..errors import CortexError
from . import common

HELP = "radius of gyration of filament beads over time (table, PNG)"

# Columns of a run's table, in order (also the CSV's, after "run").
COLUMNS = ["time_s", "rg_nm", "rg_rel", "filaments", "beads", "linkers", "motors", "branch_points"]


def add_arguments(p):
    common.add_runs_over_time(p, "PNG to write (no plot without it)")
    p.add_argument("--bound", action="store_true", help="second panel: bound linkers and motors")
    p.add_argument("--normalize", action="store_true", help="plot Rg/Rg(0) instead of Rg")
    p.add_argument("--type", type=int, help="only filaments of this type index")
    p.add_argument("--per-length", action="store_true",
                   help="weight cylinder midpoints by cylinder length instead of beads equally")
    p.add_argument("--quiet", action="store_true", help="only the summary line per run")


def table(outdir, type_index, per_length):
    """COLUMNS per snapshot with filaments, as an (n, 8) array."""
    run = common.open_run(outdir)
    rows = []
    for s in run.snapshots():
        f = s.filaments
        if f is None or len(f) == 0:
            continue
        keep = f.types == type_index if type_index is not None else np.ones(len(f), dtype=bool)
        rg, beads = geometry.radius_of_gyration(f, keep, per_length)
        rows.append([s.time, rg, np.nan, keep.sum(), beads, len(f.linkers), len(f.motors), len(f.branch_points)])
    if not rows:
        raise CortexError(f"{run.trajectory_path}: no snapshot with filaments")
    rows = np.array(rows, dtype=float)
    rows[:, 2] = rows[:, 1] / rows[0, 1]
    return rows


def print_table(label, rows, quiet):
    if not quiet:
        print(f"# {label}")
        print(f"{'t (s)':>8} {'Rg (nm)':>9} {'Rg/Rg0':>7} {'fil':>5} {'beads':>6} "
              f"{'linkers':>7} {'motors':>6} {'branch':>6}")
        for t, rg, rel, *counts in rows:
            print(f"{t:8.3f} {rg:9.1f} {rel:7.3f} " + " ".join(
                f"{int(n):{w}d}" for n, w in zip(counts, (5, 6, 7, 6, 6))))
    print(f"{label}: Rg {rows[0, 1]:.1f} -> {rows[-1, 1]:.1f} nm over {rows[-1, 0] - rows[0, 0]:.2f} s "
          f"({100 * (rows[-1, 2] - 1):+.1f}%)")


def write_csv(path, labels, tables):
    """Times, Rg and Rg/Rg(0) as floats, the counts as integers."""
    as_float, as_int = (lambda v: repr(float(v))), (lambda v: str(int(v)))
    common.write_tables_csv(path, COLUMNS, labels, tables, [as_float] * 3 + [as_int] * (len(COLUMNS) - 3))


def plot(args, labels, tables):
    plt = plotting.pyplot()
    w, h = args.size
    npanels = 2 if args.bound else 1
    fig, axes = plt.subplots(1, npanels, figsize=(w * npanels, h), squeeze=False)
    ax = axes[0, 0]
    for i, (label, rows) in enumerate(zip(labels, tables)):
        ax.plot(rows[:, 0], rows[:, 2] if args.normalize else rows[:, 1], "o-", ms=3, color=f"C{i}", label=label)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("Rg / Rg(0)" if args.normalize else "radius of gyration of actin beads (nm)")
    ax.grid(alpha=0.3)
    if len(tables) > 1:
        ax.legend(fontsize=8)
    if args.bound:
        bx = axes[0, 1]
        for i, (label, rows) in enumerate(zip(labels, tables)):
            prefix = f"{label} " if len(tables) > 1 else ""
            bx.plot(rows[:, 0], rows[:, 5], "-", color=f"C{i}", label=prefix + "linkers")
            bx.plot(rows[:, 0], rows[:, 6], "--", color=f"C{i}", label=prefix + "motors")
        bx.set_xlabel("time (s)")
        bx.set_ylabel("bound count")
        bx.grid(alpha=0.3)
        bx.legend(fontsize=7)
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    plotting.save(fig, args.out, args.dpi)
    common.wrote(args.out)


def run(args):
    labels = common.run_labels(args)
    tables = [table(d, args.type, args.per_length) for d in args.outdir]
    for label, rows in zip(labels, tables):
        print_table(label, rows, args.quiet)
    if args.csv:
        write_csv(args.csv, labels, tables)
    if args.out:
        plot(args, labels, tables)
    return 0
