#!/usr/bin/python3
"""Render a membrane of a cortex run with matplotlib, coloured by mean curvature.

Reads OUTDIR/trajectory.h5 (layout: docs/output.md):
  /snapshots/NNNNNN/membranes/<name>/vertices        (n,3) nm
  /snapshots/NNNNNN/membranes/<name>/triangles       (m,3)
  /snapshots/NNNNNN/membranes/<name>/mean_curvature  (n)   1/nm

Each face is coloured by the average of its vertices' mean curvature on a diverging
red-white-blue scale centred on zero: red = concave (H < 0), blue = convex (H > 0),
like thesis fig. 2.3. The title gives the time and the reduced volume
v = 6 sqrt(pi) V / A^(3/2) computed from the mesh.

Examples:
  render_membrane.py out                          # last snapshot -> out/membrane_last.png
  render_membrane.py out --snapshot 0 --views 3 --out start.png
  render_membrane.py out --montage 0,5,10,last --out shrink.png
  render_membrane.py out --info                   # print area, volume, v, principal semi-axes
  render_membrane.py runA runB --labels "A,B" --align --out ab.png   # last snapshots side by side

Needs numpy, h5py and matplotlib (Debian: /usr/bin/python3).
"""

import argparse
import math
import os
import sys

import numpy as np

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import colors as mcolors
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
except ImportError as e:  # pragma: no cover - depends on the interpreter
    sys.exit(f"render_membrane.py: {e}; run it with /usr/bin/python3 (Debian's numpy, h5py, matplotlib)")

# (elevation, azimuth) in degrees, and a label, for --views 3.
VIEWS = {
    3: [(20.0, -60.0, "oblique"), (0.0, -90.0, "side (x-z)"), (90.0, -90.0, "top (x-y)")]}


class UsageError(Exception):
    """A problem with the user's input: printed without a traceback, exit code 2."""


# ----------------------------------------------------------------------------- data

def trajectory_path(path):
    if os.path.isdir(path):
        path = os.path.join(path, "trajectory.h5")
    if not os.path.isfile(path):
        raise UsageError(f"{path}: no such file (give a cortex output directory or its trajectory.h5)")
    return path


def snapshot_names(h5):
    if "snapshots" not in h5 or len(h5["snapshots"]) == 0:
        raise UsageError(f"{h5.filename}: holds no /snapshots (was the run interrupted before the first snapshot?)")
    return sorted(h5["snapshots"].keys())


def resolve_snapshot(names, spec):
    """'last', 'first', an index into the snapshot list (negative counts from the end)."""
    spec = str(spec).strip()
    if spec == "last":
        return names[-1]
    if spec == "first":
        return names[0]
    try:
        i = int(spec)
    except ValueError:
        raise UsageError(f"--snapshot '{spec}': expected an integer, 'first' or 'last'") from None
    key = f"{i:06d}"
    if i >= 0 and key in names:
        return key
    if -len(names) <= i < 0:
        return names[i]
    raise UsageError(f"snapshot {spec} does not exist: the file has {len(names)} snapshots "
                     f"({names[0]} .. {names[-1]})")


def load_membrane(h5, snap, name):
    group = h5["snapshots"][snap]
    if "membranes" not in group or len(group["membranes"]) == 0:
        raise UsageError(f"snapshot {snap} holds no membranes")
    available = sorted(group["membranes"].keys())
    if name is None:
        name = available[0]
    if name not in available:
        raise UsageError(f"membrane '{name}' not in snapshot {snap}; available: {', '.join(available)}")
    m = group["membranes"][name]
    x = np.asarray(m["vertices"][:], dtype=float)
    tri = np.asarray(m["triangles"][:], dtype=np.int64)
    h = np.asarray(m["mean_curvature"][:], dtype=float) if "mean_curvature" in m else None
    return {"snapshot": snap, "name": name, "time": float(group.attrs.get("time", float("nan"))),
            "step": int(group.attrs.get("step", -1)), "x": x, "tri": tri, "H": h}


# ------------------------------------------------------------------------- geometry

def area_volume(x, tri):
    a, b, c = x[tri[:, 0]], x[tri[:, 1]], x[tri[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0
    return area, volume


def reduced_volume(area, volume):
    return 6.0 * math.sqrt(math.pi) * volume / area ** 1.5 if area > 0 else float("nan")


def principal_frame(x):
    """Centroid and principal directions of the vertex cloud, largest variance first."""
    c = x.mean(axis=0)
    _, vecs = np.linalg.eigh(np.cov((x - c).T))
    vecs = vecs[:, ::-1]                                  # descending variance
    if np.linalg.det(vecs) < 0:
        vecs[:, 2] = -vecs[:, 2]                          # keep a right-handed frame
    return c, vecs


def principal_semi_axes(x):
    """Half the extent of the vertex cloud along each principal direction (nm), descending."""
    c, vecs = principal_frame(x)
    y = (x - c) @ vecs
    semi = 0.5 * (y.max(axis=0) - y.min(axis=0))
    order = np.argsort(semi)[::-1]                        # variance and extent orders may differ
    return semi[order], y[:, order]


def classify(x):
    """Rough shape class from the principal semi-axes a1 >= a2 >= a3 (half extents of the
    vertex cloud) and, for flattened shapes, the profile along the shortest axis.

    sphere       a1/a3 < 1.05
    prolate      elongation dominates: a1/a2 > a2/a3; "(triaxial)" appended when a2/a3 > 1.1
    oblate       flattening dominates: a2/a3 >= a1/a2; "(triaxial)" appended when a1/a2 > 1.1
    discocyte    oblate with a dimple (> 5% of the thickness) on both faces at the axis,
                 the membrane crossing the axis near the mid-plane
    stomatocyte  oblate with a one-sided dimple, or crossing the axis off the mid-plane
                 by more than 20% of the thickness (a cup)
    These are heuristics for a quick label; report the semi-axes and look at the picture."""
    semi, y = principal_semi_axes(x)
    a1, a2, a3 = semi
    if a1 / a3 < 1.05:
        return "sphere", semi
    if a1 / a2 > a2 / a3:
        return "prolate" + (" (triaxial)" if a2 / a3 > 1.1 else ""), semi
    triaxial = " (triaxial)" if a1 / a2 > 1.1 else ""
    # axis of the flattened shape = shortest principal direction (z after principal_semi_axes)
    c = 0.5 * (y.max(axis=0) + y.min(axis=0))
    rho = np.hypot(y[:, 0] - c[0], y[:, 1] - c[1])
    z = y[:, 2] - c[2]
    near = rho < 0.15 * a2
    if near.sum() < 2:
        return "oblate" + triaxial, semi
    zc = z[near]
    thickness = z.max() - z.min()
    top_dimple = z.max() - zc.max()          # how far the upper face at the axis sits below the top
    bottom_dimple = zc.min() - z.min()       # how far the lower face at the axis sits above the bottom
    deep = 0.05 * thickness
    if max(top_dimple, bottom_dimple) <= deep:
        return "oblate" + triaxial, semi
    # where the membrane crosses the axis: around the mid-plane for a discocyte, pushed to
    # one side (the bottom of the invagination next to the outer wall) for a cup
    offset = abs(0.5 * (zc.max() + zc.min())) / thickness
    if offset < 0.2 and top_dimple > deep and bottom_dimple > deep:
        return "discocyte" + triaxial, semi
    return "stomatocyte" + triaxial, semi


# ------------------------------------------------------------------------ rendering

def face_values(m):
    if m["H"] is None:
        return None
    return m["H"][m["tri"]].mean(axis=1)


def shaded_colours(x, tri, values, norm, cmap):
    """RGBA per face: colormap value times a soft Lambert term so the shape reads in 3D."""
    a, b, c = x[tri[:, 0]], x[tri[:, 1]], x[tri[:, 2]]
    n = np.cross(b - a, c - a)
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    light = np.array([-0.4, -0.5, 0.77])
    light /= np.linalg.norm(light)
    shade = 0.6 + 0.4 * np.abs(n @ light)
    if values is None:
        rgba = np.tile(np.array([0.75, 0.75, 0.75, 1.0]), (len(tri), 1))
    else:
        rgba = np.array(cmap(norm(values)))
    rgba[:, :3] *= shade[:, None]
    return rgba


def draw(ax, m, x, norm, cmap, elev, azim, edges, half):
    tri = m["tri"]
    polys = x[tri]
    coll = Poly3DCollection(polys, facecolors=shaded_colours(x, tri, face_values(m), norm, cmap),
                            edgecolors=(0, 0, 0, 0.25) if edges else "none",
                            linewidths=0.2 if edges else 0.0)
    ax.add_collection3d(coll)
    c = 0.5 * (x.max(axis=0) + x.min(axis=0))
    for setter, ci in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), c):
        setter(ci - half, ci + half)
    ax.set_box_aspect((1, 1, 1))                       # equal aspect: one nm is one nm on every axis
    ax.view_init(elev=elev, azim=azim)
    ax.set_axis_off()


def colour_scale(members, clim):
    if clim is None:
        vals = [np.abs(face_values(m)) for m in members if m["H"] is not None]
        clim = float(np.percentile(np.concatenate(vals), 99)) if vals else 1.0
        clim = clim if clim > 0 else 1.0
    return mcolors.Normalize(vmin=-clim, vmax=clim), clim


def title_of(m, x):
    area, volume = area_volume(x, m["tri"])
    return f"t = {m['time']:.4g} s, v = {reduced_volume(area, volume):.3f}"


def render(members, args):
    cmap = plt.get_cmap(args.cmap)
    norm, clim = colour_scale(members, args.clim)
    if len(members) == 1 and args.views == 3:
        views = VIEWS[3]
    else:                                              # one view per snapshot
        views = [(args.elev, args.azim, "")]
    coords = []
    for m in members:
        x = m["x"]
        if args.align:
            c, vecs = principal_frame(x)
            x = (x - c) @ vecs
        coords.append(x)
    half = 0.52 * max(float((x.max(axis=0) - x.min(axis=0)).max()) for x in coords)
    ncols = len(members) * len(views)
    fig = plt.figure(figsize=(args.size * ncols + 0.9, args.size + 0.5))
    for i, (m, x) in enumerate(zip(members, coords)):
        for j, (elev, azim, label) in enumerate(views):
            ax = fig.add_subplot(1, ncols, i * len(views) + j + 1, projection="3d")
            draw(ax, m, x, norm, cmap, elev, azim, args.edges, half)
            heading = title_of(m, x) if j == 0 else ""
            if j == 0 and m.get("label"):
                heading = f"{m['label']}\n{heading}"
            ax.set_title(heading + (f"\n{label}" if label and len(views) > 1 else ""), fontsize=8)
    if any(m["H"] is not None for m in members):
        sm = plt.cm.ScalarMappable(norm=mcolors.Normalize(-clim * 1e3, clim * 1e3), cmap=cmap)
        cb = fig.colorbar(sm, ax=fig.axes, shrink=0.7, pad=0.02, fraction=0.04)
        cb.set_label("mean curvature H (1/µm)\nred concave, blue convex", fontsize=7)
        cb.ax.tick_params(labelsize=6)
    names = sorted({m["name"] for m in members})
    fig.text(0.005, 0.01, "membrane " + ", ".join(f"'{n}'" for n in names), fontsize=6, color="0.4")
    fig.subplots_adjust(left=0.0, right=0.88, bottom=0.0, top=0.84, wspace=0.0)
    fig.savefig(args.out, dpi=args.dpi)
    plt.close(fig)


def print_info(m):
    x = m["x"]
    area, volume = area_volume(x, m["tri"])
    shape, semi = classify(x)
    print(f"snapshot {m['snapshot']}  t = {m['time']:.6g} s  membrane '{m['name']}'  "
          f"{len(x)} vertices  {len(m['tri'])} triangles")
    print(f"  area {area:.6g} nm^2  volume {volume:.6g} nm^3  reduced volume {reduced_volume(area, volume):.4f}")
    print(f"  principal semi-axes {semi[0]:.1f} {semi[1]:.1f} {semi[2]:.1f} nm  shape class: {shape}")
    if m["H"] is not None:
        print(f"  mean curvature {m['H'].min():.4g} .. {m['H'].max():.4g} 1/nm")


# ------------------------------------------------------------------------------ CLI

def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="render_membrane.py",
        description="Render a membrane of a cortex run (OUTDIR/trajectory.h5) coloured by mean "
                    "curvature: red concave, white flat, blue convex.",
        epilog="Snapshots are numbered as the groups /snapshots/NNNNNN; negative numbers count "
               "from the end. Exit code 2 on bad input (missing file, snapshot or membrane).")
    p.add_argument("outdir", nargs="+",
                   help="cortex output directory (or its trajectory.h5); several give one panel each")
    p.add_argument("--snapshot", default="last", help="snapshot number, 'first' or 'last' (default: last)")
    p.add_argument("--montage", metavar="LIST",
                   help="comma-separated snapshots drawn side by side with one colour scale, "
                        "e.g. 0,5,10,last; 'all' for every snapshot (overrides --snapshot)")
    p.add_argument("--labels", metavar="LIST",
                   help="comma-separated panel captions, one per panel (e.g. 'prolate start,oblate start')")
    p.add_argument("--membrane", help="membrane name (default: the first one in the snapshot)")
    p.add_argument("--out", help="output PNG (default: OUTDIR/membrane_<snapshot>.png)")
    p.add_argument("--views", type=int, choices=(1, 3), default=1,
                   help="1: one oblique view; 3: oblique, side and top views (single snapshot)")
    p.add_argument("--align", action="store_true",
                   help="rotate into the principal axes of the vertex cloud (longest along x, shortest along z)")
    p.add_argument("--clim", type=float, help="colour limit |H| in 1/nm (default: 99th percentile of |H|)")
    p.add_argument("--cmap", default="RdBu", help="diverging matplotlib colormap, low=red (default: RdBu)")
    p.add_argument("--elev", type=float, default=20.0, help="view elevation in degrees (default 20)")
    p.add_argument("--azim", type=float, default=-60.0, help="view azimuth in degrees (default -60)")
    p.add_argument("--size", type=float, default=2.6, help="panel size in inches (default 2.6)")
    p.add_argument("--dpi", type=int, default=80, help="resolution (default 80)")
    p.add_argument("--edges", action="store_true", help="draw the mesh edges")
    p.add_argument("--info", action="store_true",
                   help="print area, volume, reduced volume, principal semi-axes and a shape class; "
                        "no picture unless --out is given")
    return p.parse_args(argv)


def load_members(args):
    """One entry per panel: the --montage snapshots of one run, or --snapshot of each run."""
    members = []
    for outdir in args.outdir:
        path = trajectory_path(outdir)
        try:
            h5 = h5py.File(path, "r")
        except OSError as e:
            raise UsageError(f"{path}: cannot read as HDF5 ({e})") from None
        with h5:
            names = snapshot_names(h5)
            if args.montage:
                specs = names if args.montage.strip() == "all" else args.montage.split(",")
                snaps = [resolve_snapshot(names, s) for s in specs]
            else:
                snaps = [resolve_snapshot(names, args.snapshot)]
            for s in snaps:
                m = load_membrane(h5, s, args.membrane)
                m["path"] = path
                members.append(m)
    if args.labels is not None:
        labels = args.labels.split(",")
        if len(labels) != len(members):
            raise UsageError(f"--labels has {len(labels)} entries for {len(members)} panels")
        for m, label in zip(members, labels):
            m["label"] = label.strip()
    return members


def main(argv=None):
    args = parse_args(argv)
    try:
        if args.montage and len(args.outdir) > 1:
            raise UsageError("--montage takes the snapshots of one run; give one OUTDIR")
        members = load_members(args)
        if args.info:
            for m in members:
                print_info(m)
            if not args.out:
                return 0
        if args.out is None:
            base = os.path.dirname(members[0]["path"])
            tag = ("montage" if args.montage or len(members) > 1
                   else "last" if args.snapshot == "last" else members[0]["snapshot"])
            args.out = os.path.join(base, f"membrane_{tag}.png")
        render(members, args)
        print(f"wrote {args.out}")
        return 0
    except UsageError as e:
        print(f"render_membrane.py: error: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
