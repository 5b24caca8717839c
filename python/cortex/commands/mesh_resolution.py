"""Edge length against mean curvature in one snapshot: did adaptive remeshing refine the
mesh where the membrane is curved? Each vertex's mean incident edge length is binned by
its |mean curvature| and compared with the sizing rule L = sqrt(6 eps / k - 3 eps^2),
clamped to [min-size, max-size] (k taken as |H|, exact on spheres; the remesher uses
the largest principal curvature, which is >= |H|). docs/remeshing.md.

  mesh-resolution OUT --mesh-size 60 -o resolution.png
"""

import numpy as np

from .. import geometry, plotting
from ..errors import CortexError
from . import common

HELP = "edge length against curvature, with the remesher's sizing rule (PNG)"


def add_arguments(p):
    common.add_outdirs(p, many=False)
    common.add_out(p, "output PNG (default: OUTDIR/mesh_resolution.png)")
    common.add_snapshot(p, "last")
    common.add_membrane(p)
    common.add_figure(p, "5.5,3.6", 90)
    p.add_argument("--mesh-size", type=common.positive_float, default=60.0, help="the membrane's mesh_size in nm (default 60)")
    p.add_argument("--min-size", type=common.positive_float, help="remesher's min_size (default mesh-size/4)")
    p.add_argument("--max-size", type=common.positive_float, help="remesher's max_size (default 2 mesh-size)")
    p.add_argument("--tolerance", type=common.positive_float, help="remesher's curvature tolerance eps (default mesh-size/120)")


def run(args):
    r = common.open_run(args.outdir)
    snapshot = r.snapshot(common.snapshot_indices(r, args.snapshot)[0])
    m = common.membranes_of(snapshot, args.membrane)[0]
    if m.mean_curvature is None:
        raise CortexError(f"{r.trajectory_path}: snapshot {snapshot.name}, membrane '{m.name}' has no mean_curvature")
    lo = args.min_size or args.mesh_size / 4
    hi = args.max_size or 2 * args.mesh_size
    eps = args.tolerance or args.mesh_size / 120
    out = args.out or common.default_out(r, "mesh_resolution.png")

    edge = geometry.vertex_edge_lengths(m.vertices, m.triangles)
    k = np.abs(m.mean_curvature)
    bins = np.quantile(k, np.linspace(0, 1, 11))
    centres, means = [], []
    for b0, b1 in zip(bins[:-1], bins[1:]):
        sel = (k >= b0) & (k <= b1)
        centres.append(np.median(k[sel]))
        means.append(edge[sel].mean())
    kk = np.linspace(max(k.min(), 1e-6), max(k.max(), 2e-6), 200)
    rule = np.clip(np.minimum(np.sqrt(np.maximum(6 * eps / kk - 3 * eps ** 2, 0)), args.mesh_size), lo, hi)

    plt = plotting.pyplot()
    fig, ax = plt.subplots(figsize=args.size)
    ax.scatter(k * 1e3, edge, s=2, alpha=0.25, color="0.5", label="vertices")
    ax.plot(np.array(centres) * 1e3, means, "o-", color="C0", label="mean per decile of |H|")
    ax.plot(kk * 1e3, rule, "--", color="C3", label="sizing rule at k = |H|")
    ax.set_xlabel("|mean curvature| (1/µm)")
    ax.set_ylabel("mean incident edge length (nm)")
    ax.set_title(f"t = {snapshot.time:.3g} s, membrane '{m.name}', {len(m.vertices)} vertices")
    ax.legend(fontsize=8)
    fig.tight_layout()
    plotting.save(fig, out, args.dpi)
    flat = edge[k <= np.quantile(k, 0.2)].mean()
    curved = edge[k >= np.quantile(k, 0.9)].mean()
    print(f"mean edge: flattest 20% of vertices {flat:.1f} nm, most curved 10% {curved:.1f} nm")
    common.wrote(out)
    return 0
