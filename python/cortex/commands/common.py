"""Flags every command spells the same way, and the look-ups behind them."""

import argparse
import math
import os

from .. import geometry, plotting
from ..errors import CortexError
from ..run import Run


def add_outdirs(parser, many):
    if many:
        parser.add_argument("outdir", nargs="+", help="cortex output folders (or their trajectory.h5)")
    else:
        parser.add_argument("outdir", help="cortex output folder (or its trajectory.h5)")


def add_out(parser, what, image=True):
    """-o FILE; a picture's name must end in a format matplotlib writes (image=False: the
    command checks it, as `movie` does for its MP4)."""
    parser.add_argument("-o", "--out", metavar="FILE", help=what, type=image_file if image else str)


def add_snapshot(parser, default):
    parser.add_argument("--snapshot", default=default, metavar="LIST",
                        help="snapshots, comma-separated: N (from 0; negative counts from the end), "
                             f"first, last, or all (default: {default})")


def add_runs_over_time(parser, what):
    """The flags of a command that tabulates runs over time and may plot them: the
    output folders, -o (a PNG: `what`), figure size and resolution, legend labels, a CSV
    of the tables and a title; the command adds its own."""
    add_outdirs(parser, many=True)
    add_out(parser, what)
    add_figure(parser, "6,4", 100)
    parser.add_argument("--labels", metavar="LIST", help="comma-separated legend labels, one per run")
    parser.add_argument("--csv", metavar="FILE", help="also write the tables as CSV (run column first)")
    parser.add_argument("--title", help="figure title")


def add_membrane(parser):
    parser.add_argument("--membrane", metavar="NAME", help="membrane name (default: every membrane "
                        "where a picture can hold several, else the first in the run's config)")


# Types of numeric and file flags (argparse `type=`): a value that makes no sense is
# refused while the command line is parsed, with exit code 2 and a message naming the
# flag, before any run is read; float() alone accepts nan and inf, and numpy or
# matplotlib fail on zero or negative counts and sizes with a traceback, or silently
# compute nothing (`--split nan` counts no copy past the barrier).

def finite_float(text):
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"'{text}': expected a finite number")
    return value


def positive_float(text):
    value = finite_float(text)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"'{text}': expected a number > 0")
    return value


def positive_int(text):
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"'{text}': expected a whole number >= 1")
    return value


def image_file(path):
    """A picture's file name: its extension picks the format, so it must be one matplotlib
    writes (without one, matplotlib would write FILE.png instead of FILE)."""
    formats = plotting.image_formats()
    if os.path.splitext(path)[1][1:].lower() not in formats:
        raise argparse.ArgumentTypeError(f"'{path}': expected a picture file ending in "
                                         + ", ".join(f".{f}" for f in sorted(formats)))
    return path


def size_pair(spec):
    """--size W[,H] in inches; H = W when one number is given."""
    try:
        values = [positive_float(v) for v in spec.split(",")]
    except argparse.ArgumentTypeError:
        values = []
    if len(values) not in (1, 2):
        raise argparse.ArgumentTypeError(f"'{spec}': expected W or W,H in inches, e.g. 4 or 6,4")
    return values[0], values[-1]


def add_figure(parser, size, dpi):
    parser.add_argument("--size", type=size_pair, default=size, metavar="W[,H]",
                        help=f"panel size in inches (default {size})")
    parser.add_argument("--dpi", type=positive_int, default=dpi, help=f"resolution (default {dpi})")


def open_run(outdir):
    """A run with at least one snapshot."""
    run = Run(outdir)
    if len(run) == 0:
        raise CortexError(f"{run.trajectory_path}: holds no snapshots "
                          "(was the run stopped before its first snapshot?)")
    return run


def snapshot_indices(run, spec):
    """Indices named by a --snapshot list such as `0,5,last` or `all`."""
    n = len(run)
    out = []
    for item in str(spec).split(","):
        item = item.strip()
        if item == "all":
            out.extend(range(n))
        elif item in ("first", "last"):
            out.append(0 if item == "first" else n - 1)
        else:
            try:
                i = int(item)
            except ValueError:
                raise CortexError(f"--snapshot '{item}': expected N, first, last or all") from None
            if not -n <= i < n:
                raise CortexError(f"{run.trajectory_path}: no snapshot {i} (the run has {n}: 0 .. {n - 1})")
            out.append(i % n)
    return out


def membranes_of(snapshot, name=None):
    """The snapshot's membranes, or only the one named; an error when there is none."""
    membranes = snapshot.membranes
    where = f"{snapshot.run.trajectory_path}: snapshot {snapshot.name}"
    if not membranes:
        raise CortexError(f"{where} holds no membranes")
    if name is None:
        return list(membranes.values())
    if name not in membranes:
        raise CortexError(f"{where} has no membrane '{name}' (it has {', '.join(membranes)})")
    return [membranes[name]]


def closed_membrane(run, name):
    """The first snapshot's membrane (the one named, or the first), which must be closed."""
    membrane = membranes_of(run.snapshot(0), name)[0]
    if not geometry.is_closed(membrane.triangles):
        raise CortexError(f"{run.trajectory_path}: membrane '{membrane.name}' is open: this measures a vesicle")
    return membrane


def species_of(membrane, name, where):
    """The membrane species `name`, or the membrane's only one when name is None."""
    if not membrane.species:
        raise CortexError(f"{where}: membrane '{membrane.name}' has no species")
    if name is None:
        if len(membrane.species) > 1:
            raise CortexError(f"{where}: membrane '{membrane.name}' has species {', '.join(sorted(membrane.species))}; "
                              "choose one with --species")
        return next(iter(membrane.species))
    if name not in membrane.species:
        raise CortexError(f"{where}: membrane '{membrane.name}' has no species '{name}' "
                          f"(it has {', '.join(sorted(membrane.species))})")
    return name


def filaments_of(snapshot):
    filaments = snapshot.filaments
    if filaments is None:
        raise CortexError(f"{snapshot.run.trajectory_path}: snapshot {snapshot.name} holds no filaments")
    return filaments


def default_out(run, filename):
    return os.path.join(run.path, filename)


def split_labels(spec, count, what):
    """--labels: one comma-separated caption per panel or run."""
    labels = [s.strip() for s in spec.split(",")]
    if len(labels) != count:
        raise CortexError(f"--labels has {len(labels)} entries for {count} {what}")
    return labels


def run_labels(args):
    """A caption per run folder: --labels, else each folder's name."""
    if args.labels:
        return split_labels(args.labels, len(args.outdir), "runs")
    return [os.path.basename(os.path.normpath(d)) for d in args.outdir]


def print_rows(title, columns, rows):
    """Prints '# title', a header of right-aligned column names and each row of a table
    over time; `columns`: (name, format) pairs such as ("t (s)", "8.3f"), whose leading
    number is the column's width."""
    print(f"# {title}")
    print(" ".join(f"{name:>{int(spec.split('.')[0])}}" for name, spec in columns))
    for row in rows:
        print(" ".join(f"{value:{spec}}" for value, (_, spec) in zip(row, columns)))


def write_tables_csv(path, columns, labels, tables, formats=None):
    """Per-run tables as one CSV: a run column, then `columns`; values as repr(float)
    unless `formats` gives a function per column."""
    formats = formats or [lambda v: repr(float(v))] * len(columns)
    try:
        with open(path, "w") as fh:
            fh.write(",".join(["run"] + columns) + "\n")
            for label, rows in zip(labels, tables):
                for row in rows:
                    fh.write(",".join([label] + [f(v) for f, v in zip(formats, row)]) + "\n")
    except OSError as e:
        raise CortexError(f"{path}: cannot write ({e.strerror})") from None


def plot_over_time(args, labels, tables, ylabel, decorate=None):
    """Column 1 of every run's table against its time column 0, one line per run, to
    args.out; `decorate(ax)` adds what a command needs beyond that."""
    plt = plotting.pyplot()
    fig, ax = plt.subplots(figsize=args.size)
    for i, (label, rows) in enumerate(zip(labels, tables)):
        ax.plot(rows[:, 0], rows[:, 1], "-", color=f"C{i}", label=label)
    ax.set_xlabel("time (s)")
    ax.set_ylabel(ylabel)
    if decorate:
        decorate(ax)
    ax.grid(alpha=0.3)
    if len(tables) > 1:
        ax.legend(fontsize=8)
    if args.title:
        ax.set_title(args.title)
    fig.tight_layout()
    plotting.save(fig, args.out, args.dpi)
    wrote(args.out)


def wrote(path):
    print(f"wrote {path} ({os.path.getsize(path) // 1024} KB)")
