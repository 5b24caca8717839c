"""Render membranes coloured by mean curvature: red concave, white flat, blue convex
(thesis fig. 2.3). Each panel is titled with the time and the reduced volume computed
from the mesh (or "open" for a membrane with a boundary).

  membrane OUT                                  last snapshot -> OUT/membrane_last.png
  membrane OUT --snapshot 0 --views 3 -o start.png
  membrane OUT --snapshot 0,5,10,last --align -o path.png    one colour scale
  membrane RUN1 RUN2 --labels "prolate,oblate" -o cmp.png     one panel per run
  membrane OUT --info                                         numbers only
"""

import numpy as np

from .. import geometry, plotting, report
from ..errors import CortexError
from . import common

HELP = "render membranes coloured by mean curvature (PNG)"

# (elevation, azimuth) in degrees and a caption per view of --views 3.
THREE_VIEWS = [(20.0, -60.0, "oblique"), (0.0, -90.0, "side (x-z)"), (90.0, -90.0, "top (x-y)")]


def add_arguments(p):
    common.add_outdirs(p, many=True)
    common.add_out(p, "output PNG (default: OUTDIR/membrane_<snapshot>.png)")
    common.add_snapshot(p, "last")
    common.add_membrane(p)
    common.add_figure(p, "2.6", 80)
    p.add_argument("--labels", metavar="LIST", help="comma-separated panel captions, one per panel")
    p.add_argument("--views", type=int, choices=(1, 3), default=1,
                   help="1: one oblique view; 3: oblique, side and top views (one panel only)")
    p.add_argument("--align", action="store_true",
                   help="rotate into the principal axes of the vertex cloud (longest along x, shortest along z)")
    p.add_argument("--clim", type=common.positive_float, help="colour limit |H| in 1/nm (default: 99th percentile of |H|)")
    p.add_argument("--cmap", default="RdBu", help="diverging colormap, low = red (default RdBu)")
    p.add_argument("--elev", type=common.finite_float, default=20.0, help="view elevation in degrees (default 20)")
    p.add_argument("--azim", type=common.finite_float, default=-60.0, help="view azimuth in degrees (default -60)")
    p.add_argument("--edges", action="store_true", help="draw the mesh edges")
    p.add_argument("--info", action="store_true",
                   help="print area, volume, reduced volume, principal semi-axes and a shape class; "
                        "no picture unless -o is given")


def panels(args):
    """(snapshot, membrane) per panel: every --snapshot of every run."""
    out = []
    for outdir in args.outdir:
        run = common.open_run(outdir)
        for i in common.snapshot_indices(run, args.snapshot):
            snapshot = run.snapshot(i)
            out.append((snapshot, common.membranes_of(snapshot, args.membrane)[0]))
    return out


def title(snapshot, membrane, vertices):
    if not geometry.is_closed(membrane.triangles):
        return f"t = {snapshot.time:.4g} s, open"
    area, volume = geometry.area_volume(vertices, membrane.triangles)
    return f"t = {snapshot.time:.4g} s, v = {geometry.reduced_volume(area, volume):.3f}"


def render(args, members):
    plt = plotting.pyplot()
    cmap = plt.get_cmap(args.cmap)
    limit = args.clim or plotting.curvature_limit([m for _, m in members])
    norm = plotting.curvature_norm(limit)
    views = THREE_VIEWS if args.views == 3 else [(args.elev, args.azim, "")]
    coords = []
    for _, m in members:
        x = m.vertices
        if args.align:
            c, vecs = geometry.principal_frame(x)
            x = (x - c) @ vecs
        coords.append(x)
    # one scale for every panel: each is centred on its membrane, all as large as the largest
    half = 0.52 * max(float(np.ptp(x, axis=0).max()) for x in coords)
    ncols = len(members) * len(views)
    w, h = args.size
    fig = plt.figure(figsize=(w * ncols + 0.9, h + 0.5))
    for i, ((snapshot, m), x) in enumerate(zip(members, coords)):
        centre = 0.5 * (x.max(axis=0) + x.min(axis=0))
        for j, (elev, azim, caption) in enumerate(views):
            ax = fig.add_subplot(1, ncols, i * len(views) + j + 1, projection="3d")
            plotting.add_membrane(ax, x, m, norm, cmap, args.edges)
            plotting.set_limits(ax, centre - half, centre + half)
            ax.view_init(elev=elev, azim=azim)
            ax.set_axis_off()
            heading = title(snapshot, m, x) if j == 0 else ""
            if j == 0 and args.labels:
                heading = f"{args.labels[i]}\n{heading}"
            ax.set_title(heading + (f"\n{caption}" if caption else ""), fontsize=8)
    if any(m.mean_curvature is not None for _, m in members):
        plotting.curvature_colorbar(fig, limit, cmap)
    names = sorted({m.name for _, m in members})
    fig.text(0.005, 0.01, "membrane " + ", ".join(f"'{n}'" for n in names), fontsize=6, color="0.4")
    fig.subplots_adjust(left=0.0, right=0.88, bottom=0.0, top=0.84, wspace=0.0)
    plotting.save(fig, args.out, args.dpi)


def run(args):
    members = panels(args)
    if args.views == 3 and len(members) > 1:
        raise CortexError("--views 3 draws one panel: give one OUTDIR and one --snapshot")
    if args.labels is not None:
        args.labels = common.split_labels(args.labels, len(members), "panels")
    if args.info:
        for snapshot, m in members:
            print("\n".join(report.membrane_lines(snapshot, m)))
        if not args.out:
            return 0
    if args.out is None:
        tag = "montage" if len(members) > 1 else members[0][0].name
        tag = "last" if args.snapshot == "last" and len(members) == 1 else tag
        args.out = common.default_out(members[0][0].run, f"membrane_{tag}.png")
    render(args, members)
    common.wrote(args.out)
    return 0
