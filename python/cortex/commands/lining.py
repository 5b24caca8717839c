"""Filaments lining a vesicle (thesis fig. 2.4a). Per snapshot: the share of filament
length within a distance of the membrane (cylinder midpoints against the nearest
vertex), how those cylinders lie (mean |cos| of their angle to the membrane normal
there: 0 parallel to the membrane, 1/2 for random directions, 1 pointing into it), and
the membrane's shape: its excess area over the sphere of its volume, A/(4πR_V²) − 1, and
the spread of its vertices' distances from the volume's centroid, sd/mean (both 0 for
a sphere).

  lining OUT                          table
  lining A B --labels a,b -o lining.png --csv lining.csv
"""

import numpy as np

from .. import geometry
from . import common

HELP = "filaments lining a vesicle: share of length near the membrane, its alignment, the membrane's roughness"

COLUMNS = ["time_s", "near_fraction", "near_mean_abs_cos", "excess_area", "radius_sd_over_mean"]


def add_arguments(p):
    common.add_runs_over_time(p, "PNG of the near fraction to write (no plot without it)")
    common.add_membrane(p)
    p.add_argument("--within", type=float, default=50.0, help="distance from the membrane, nm (default 50)")


def vertex_normals(vertices, triangles):
    """Unit area-weighted vertex normals (outward for an outward-oriented mesh)."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    face = np.cross(b - a, c - a)
    normals = np.zeros_like(vertices)
    for k in range(3):
        np.add.at(normals, triangles[:, k], face)
    return normals / np.linalg.norm(normals, axis=1)[:, None]


def lining(membrane, filaments, within):
    """(near fraction, mean |cos| of the near cylinders to the normal) of the filaments."""
    segments = [(line[:-1], line[1:]) for line in filaments.polylines if len(line) > 1]
    if not segments:
        return np.nan, np.nan
    starts = np.concatenate([s for s, _ in segments])
    ends = np.concatenate([e for _, e in segments])
    axis = ends - starts
    length = np.linalg.norm(axis, axis=1)
    middle = 0.5 * (starts + ends)
    normals = vertex_normals(membrane.vertices, membrane.triangles)
    nearest = np.empty(len(middle), dtype=int)
    distance = np.empty(len(middle))
    for i in range(0, len(middle), 256):  # in blocks: a cylinder-by-vertex table at a time
        d2 = ((middle[i:i + 256, None, :] - membrane.vertices[None, :, :]) ** 2).sum(axis=2)
        nearest[i:i + 256] = d2.argmin(axis=1)
        distance[i:i + 256] = np.sqrt(d2.min(axis=1))
    near = distance < within
    fraction = float(length[near].sum() / length.sum())
    if not near.any():
        return fraction, np.nan
    cos = np.abs((axis[near] / length[near][:, None] * normals[nearest[near]]).sum(axis=1))
    return fraction, float(np.average(cos, weights=length[near]))


def roughness(membrane):
    """(excess area over the sphere of the enclosed volume, sd/mean of the vertices'
    distances from the volume's centroid)."""
    volume, centre = geometry.volume_centroid(membrane.vertices, membrane.triangles)
    area, _ = geometry.area_volume(membrane.vertices, membrane.triangles)
    radius = (3 * abs(volume) / (4 * np.pi)) ** (1 / 3)
    r = np.linalg.norm(membrane.vertices - centre, axis=1)
    return float(area / (4 * np.pi * radius**2) - 1), float(r.std() / r.mean())


def table(outdir, membrane_name, within):
    run = common.open_run(outdir)
    membrane = common.closed_membrane(run, membrane_name)
    rows = []
    for s in run.snapshots():
        m, f = s.membranes.get(membrane.name), common.filaments_of(s)
        if m is not None:
            rows.append([s.time, *lining(m, f, within), *roughness(m)])
    return np.array(rows, dtype=float), membrane.name


def run(args):
    labels = common.run_labels(args)
    tables = []
    for label, outdir in zip(labels, args.outdir):
        rows, name = table(outdir, args.membrane, args.within)
        tables.append(rows)
        common.print_rows(f"{label}: membrane '{name}', filaments within {args.within:g} nm of it",
                          [("t (s)", "8.3f"), ("near", "6.3f"), ("|cos|", "6.3f"), ("excess area", "12.5f"),
                           ("r sd/mean", "10.5f")], rows)
        last = rows[-1]
        print(f"{label}: at t = {last[0]:g} s {100 * last[1]:.0f}% of the filament length within {args.within:g} nm "
              f"of the membrane, |cos| to its normal {last[2]:.2f} (random: 0.50), excess area {last[3]:.4f}, "
              f"radius sd/mean {last[4]:.4f}")
    if args.csv:
        common.write_tables_csv(args.csv, COLUMNS, labels, tables)
    if args.out:
        common.plot_over_time(args, labels, tables, f"filament length within {args.within:g} nm of the membrane")
    return 0
