"""Filaments lining a vesicle (thesis fig. 2.4a). Per snapshot: the share of filament
length within a distance of the membrane (cylinder midpoints against the nearest
vertex), how those cylinders lie (mean |cos| of their angle to the membrane normal
there: 0 parallel to the membrane, 1/2 for random directions, 1 pointing into it), and
the membrane's shape: its excess area over the sphere of its volume, A/(4πR_V²) − 1, and
the spread of its vertices' distances from the volume's centroid, sd/mean (both 0 for
a sphere). Ruffles, the thesis' small bumps as opposed to the vesicle deforming as a
whole: the vertices' distance from the centroid as a function of direction, r(u), less
its least-squares fit by the spherical harmonics of degree l ≤ 4 (polynomials of degree
≤ 4 in u; weighted by each vertex's third of its triangles' area, so a refined region
does not count twice). The fit takes up the whole-body shapes (ellipsoids, pears,
lemons); what is left are features narrower than about a fifth of the circumference.
The rms of that residual and its largest outward value, in nm (0 for any ellipsoid
close to a sphere), and its bumps: the connected patches of membrane standing more than
`--bump` nm (default 10) outside the fit, counted, with their mean diameter 2√(A/π). A
vesicle strongly deformed as a whole (a flattened one's rim) also leaves a residual:
few, wide patches where ruffles are many and narrow. Meaningful while the vesicle is
star-shaped about its centroid, so not for one with tubes.

  lining OUT                          table
  lining A B --labels a,b -o lining.png --csv lining.csv
"""

import numpy as np

from .. import geometry
from . import common

HELP = ("filaments lining a vesicle: share of length near the membrane, its alignment, the membrane's roughness "
        "and ruffles")

COLUMNS = ["time_s", "near_fraction", "near_mean_abs_cos", "excess_area", "radius_sd_over_mean", "ruffle_rms_nm",
           "ruffle_max_nm", "bumps", "bump_diameter_nm"]
RUFFLE_DEGREE = 4  # spherical harmonics up to this degree are the whole-body shape


def add_arguments(p):
    common.add_runs_over_time(p, "PNG of the near fraction to write (no plot without it)")
    common.add_membrane(p)
    p.add_argument("--within", type=common.positive_float, default=50.0, help="distance from the membrane, nm (default 50)")
    p.add_argument("--bump", type=common.positive_float, default=10.0,
                   help="height outside the whole-body shape that makes a bump, nm (default 10)")


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


def direction_polynomials(u, degree):
    """Every monomial x^i y^j z^k with i + j + k ≤ degree of the unit vectors u, as columns:
    on the sphere they span the spherical harmonics of degree ≤ `degree`."""
    return np.stack([u[:, 0] ** i * u[:, 1] ** j * u[:, 2] ** k
                     for i in range(degree + 1) for j in range(degree + 1 - i) for k in range(degree + 1 - i - j)],
                    axis=1)


def patches(mask, triangles):
    """Connected components of the vertices in `mask` over the mesh's edges: a label per
    vertex (−1 outside the mask). Each vertex takes the least label of its masked
    neighbours until none changes."""
    label = np.where(mask, np.arange(len(mask)), -1)
    edges = np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    edges = edges[mask[edges[:, 0]] & mask[edges[:, 1]]]
    while True:
        low = np.minimum(label[edges[:, 0]], label[edges[:, 1]])
        new = label.copy()
        np.minimum.at(new, edges[:, 0], low)
        np.minimum.at(new, edges[:, 1], low)
        new[mask] = new[new[mask]]  # jump along the chain of labels
        if np.array_equal(new, label):
            return label
        label = new


def ruffles(membrane, bump=10.0, degree=RUFFLE_DEGREE):
    """[rms, largest outward value] in nm of r(u) − its fit by harmonics of degree ≤
    `degree`, then [the number of patches standing more than `bump` nm outside the fit,
    their mean diameter 2√(A/π) in nm (nan without any)]."""
    _, centre = geometry.volume_centroid(membrane.vertices, membrane.triangles)
    offset = membrane.vertices - centre
    r = np.linalg.norm(offset, axis=1)
    basis = direction_polynomials(offset / r[:, None], degree)
    w = np.sqrt(membrane.cell_areas())
    coefficients = np.linalg.lstsq(basis * w[:, None], r * w, rcond=None)[0]
    residual = r - basis @ coefficients
    label = patches(residual > bump, membrane.triangles)
    _, where = np.unique(label[label >= 0], return_inverse=True)
    areas = np.bincount(where, weights=w[label >= 0] ** 2)
    diameter = float(np.mean(2 * np.sqrt(areas / np.pi))) if len(areas) else np.nan
    return [float(np.sqrt(np.average(residual**2, weights=w**2))), float(residual.max()), len(areas), diameter]


def table(outdir, membrane_name, within, bump):
    run = common.open_run(outdir)
    membrane = common.closed_membrane(run, membrane_name)
    rows = []
    for s in run.snapshots():
        m, f = s.membranes.get(membrane.name), common.filaments_of(s)
        if m is not None:
            rows.append([s.time, *lining(m, f, within), *roughness(m), *ruffles(m, bump)])
    return np.array(rows, dtype=float), membrane.name


def run(args):
    labels = common.run_labels(args)
    tables = []
    for label, outdir in zip(labels, args.outdir):
        rows, name = table(outdir, args.membrane, args.within, args.bump)
        tables.append(rows)
        common.print_rows(f"{label}: membrane '{name}', filaments within {args.within:g} nm of it",
                          [("t (s)", "8.3f"), ("near", "6.3f"), ("|cos|", "6.3f"), ("excess area", "12.5f"),
                           ("r sd/mean", "10.5f"), ("ruffle rms", "10.2f"), ("ruffle max", "10.2f"), ("bumps", "6.0f"),
                           ("bump diam", "10.0f")], rows)
        last = rows[-1]
        print(f"{label}: at t = {last[0]:g} s {100 * last[1]:.0f}% of the filament length within {args.within:g} nm "
              f"of the membrane, |cos| to its normal {last[2]:.2f} (random: 0.50), excess area {last[3]:.4f}, "
              f"radius sd/mean {last[4]:.4f}, ruffles {last[5]:.1f} nm rms (largest {last[6]:.1f} nm) beyond "
              f"the harmonics of degree ≤ {RUFFLE_DEGREE}, {last[7]:.0f} bumps over {args.bump:g} nm "
              f"(mean diameter {last[8]:.0f} nm)")
    if args.csv:
        common.write_tables_csv(args.csv, COLUMNS, labels, tables)
    if args.out:
        common.plot_over_time(args, labels, tables, f"filament length within {args.within:g} nm of the membrane")
    return 0
