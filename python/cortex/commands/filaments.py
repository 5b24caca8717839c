"""Render the filament network: filaments as polylines, cross-linkers green, motors red,
Arp2/3 branch points orange; every panel on the same axes at equal scale, so a
contraction or a growth front reads directly. Titles give the time, counts and the
beads' radius of gyration.

  filaments OUT                                   first + last -> OUT/filaments.png
  filaments OUT --snapshot 0,5,last -o net.png
  filaments OUT --box 0,0,0,2000,2000,2000 --elev 20 --azim -60
  filaments OUT --views 2 --axis y --wall z=1000 --ends -o arp.png
"""

import numpy as np

from .. import geometry, plotting
from ..errors import CortexError
from . import common

HELP = "render filaments, linkers, motors and branch points (PNG)"

# (elevation, azimuth) looking along each axis, for the second of --views 2.
ALONG = {"x": (0, 0), "y": (0, -90), "z": (90, -90)}


def add_arguments(p):
    common.add_outdirs(p, many=False)
    common.add_out(p, "output PNG (default: OUTDIR/filaments.png)")
    common.add_snapshot(p, "first,last")
    common.add_figure(p, "4.2", 100)
    p.add_argument("--box", help="axis limits xmin,ymin,zmin,xmax,ymax,zmax in nm (default: the beads' extent)")
    p.add_argument("--views", type=int, default=1, choices=(1, 2), help="1: oblique; 2: oblique + along --axis")
    p.add_argument("--axis", default="z", choices=("x", "y", "z"), help="viewing axis of the second view")
    p.add_argument("--elev", type=common.finite_float, default=22.0, help="view elevation in degrees (default 22)")
    p.add_argument("--azim", type=common.finite_float, default=-55.0, help="view azimuth in degrees (default -55)")
    p.add_argument("--wall", action="append", metavar="AXIS=VALUE",
                   help="draw a translucent wall plane, e.g. z=1000 (nm; repeatable)")
    p.add_argument("--no-linkers", action="store_true", help="leave out cross-linkers")
    p.add_argument("--no-motors", action="store_true", help="leave out motors")
    p.add_argument("--ends", action="store_true", help="mark plus ends with dots")
    p.add_argument("--lw", type=common.positive_float, default=0.8, help="filament line width")
    p.add_argument("--zoom", type=common.positive_float, default=1.2, help="3D axes zoom (default 1.2)")
    p.add_argument("--title", help="figure title")


def box_limits(spec, networks):
    if spec is None:
        return plotting.bounds([f.beads for f in networks])
    try:
        b = [float(v) for v in spec.split(",")]
    except ValueError:
        b = []
    if len(b) != 6:
        raise CortexError(f"--box '{spec}': expected 6 numbers xmin,ymin,zmin,xmax,ymax,zmax")
    return np.array(b[:3]), np.array(b[3:])


def walls(specs):
    """(axis index, position) per --wall AXIS=VALUE."""
    out = []
    for spec in specs or []:
        axis, _, value = spec.partition("=")
        try:
            out.append(("xyz".index(axis.strip()), float(value)))
        except ValueError:
            raise CortexError(f"--wall '{spec}': expected AXIS=VALUE, e.g. z=1000") from None
    return out


def add_wall(ax, axis, value, lo, hi):
    others = [i for i in range(3) if i != axis]
    u, v = np.meshgrid([lo[others[0]], hi[others[0]]], [lo[others[1]], hi[others[1]]])
    xyz = [None] * 3
    xyz[axis], xyz[others[0]], xyz[others[1]] = np.full_like(u, value), u, v
    ax.plot_surface(*xyz, color="0.5", alpha=0.15, shade=False)


def title(snapshot, f):
    rg, _ = geometry.radius_of_gyration(f)
    return (f"t = {snapshot.time:.2f} s: {len(f)} filaments, {len(f.beads)} beads\n"
            f"{len(f.linkers)} linkers, {len(f.motors)} motors, "
            f"{len(f.branch_points)} branches, Rg = {rg:.0f} nm")


def run(args):
    r = common.open_run(args.outdir)
    snapshots = [r.snapshot(i) for i in common.snapshot_indices(r, args.snapshot)]
    networks = [common.filaments_of(s) for s in snapshots]
    lo, hi = box_limits(args.box, networks)
    planes = walls(args.wall)
    out = args.out or common.default_out(r, "filaments.png")

    plt = plotting.pyplot()
    views = [(args.elev, args.azim)] + ([ALONG[args.axis]] if args.views == 2 else [])
    ncol, nrow = len(snapshots), len(views)
    w, h = args.size
    fig = plt.figure(figsize=(w * ncol, h * nrow))
    for c, (s, f) in enumerate(zip(snapshots, networks)):
        for row, (elev, azim) in enumerate(views):
            ax = fig.add_subplot(nrow, ncol, row * ncol + c + 1, projection="3d")
            plotting.add_filaments(ax, f, not args.no_linkers, not args.no_motors, args.ends, args.lw)
            for axis, value in planes:
                add_wall(ax, axis, value, lo, hi)
            plotting.set_limits(ax, lo, hi, args.zoom)
            ax.view_init(elev=elev, azim=azim)
            ax.tick_params(labelsize=6, pad=0)
            for name in "xyz":
                getattr(ax, f"set_{name}label")(f"{name} (nm)", fontsize=7, labelpad=-2)
            if row == 1:                    # the axis we look along: no crowded ticks
                getattr(ax, f"set_{args.axis}ticklabels")([])
                getattr(ax, f"set_{args.axis}label")("")
            else:
                ax.set_title(title(s, f), fontsize=8)
    plotting.filament_legend(fig, not args.no_linkers and any(len(f.linkers) for f in networks),
                             not args.no_motors and any(len(f.motors) for f in networks),
                             any(len(f.branch_points) for f in networks), args.ends)
    if args.title:
        fig.suptitle(args.title, fontsize=10)
    fig.subplots_adjust(left=0.02, right=0.98, top=0.9 if nrow > 1 else 0.8,
                        bottom=0.07 if nrow > 1 else 0.12, wspace=0.05, hspace=0.05)
    plotting.save(fig, out, args.dpi)
    common.wrote(out)
    return 0
