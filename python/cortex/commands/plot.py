"""Observables columns against time (or --x COLUMN), one panel per column, from the run's
observables table. Columns are named by their summary.json path (`info OUT` lists them);
shell patterns pick several: `membranes.*.reduced_volume`.

  plot OUT membranes.vesicle.reduced_volume -o v.png
  plot OUT 'membranes.*.energy.total' filaments.total_length --x time
"""

import numpy as np

from .. import plotting
from . import common

HELP = "plot observables columns over time (PNG)"


def add_arguments(p):
    common.add_outdirs(p, many=False)
    p.add_argument("columns", nargs="+", metavar="COLUMN", help="observables column or shell pattern")
    common.add_out(p, "output PNG (default: OUTDIR/observables.png)")
    common.add_figure(p, "6,2.4", 100)
    p.add_argument("--x", default="time", metavar="COLUMN", help="column on the horizontal axis (default time)")


def run(args):
    r = common.open_run(args.outdir)
    table = r.observables
    x = table[args.x]
    columns = [c for pattern in args.columns for c in table.matching(pattern)]
    out = args.out or common.default_out(r, "observables.png")

    plt = plotting.pyplot()
    w, h = args.size
    fig, axes = plt.subplots(len(columns), 1, figsize=(w, h * len(columns)), sharex=True, squeeze=False)
    for ax, name in zip(axes[:, 0], columns):
        y = table[name]
        ax.plot(x, y, "o-", ms=3)
        ax.set_title(name, fontsize=8, loc="left")
        ax.grid(alpha=0.3)
        if not np.isfinite(y).any():
            ax.text(0.5, 0.5, "no values (NaN)", transform=ax.transAxes, ha="center", color="0.4")
    axes[-1, 0].set_xlabel(f"{args.x} (s)" if args.x == "time" else args.x)
    fig.suptitle(r.path, fontsize=8)
    fig.tight_layout()
    plotting.save(fig, out, args.dpi)
    common.wrote(out)
    return 0
