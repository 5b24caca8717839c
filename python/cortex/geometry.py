"""Numbers computed from a snapshot's arrays: membrane area, volume, shape class,
edge lengths; the radius of gyration of filament beads."""

import math

import numpy as np


def area_volume(vertices, triangles):
    """Area (nm^2) and enclosed volume (nm^3, meaningful for closed meshes only)."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0
    return float(area), float(volume)


def volume_centroid(vertices, triangles):
    """Enclosed volume (nm^3) and its centroid of a closed, outward-oriented mesh
    (tetrahedra on the origin)."""
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    volumes = np.einsum("ij,ij->i", a, np.cross(b, c)) / 6.0
    return float(volumes.sum()), ((a + b + c) / 4.0 * volumes[:, None]).sum(axis=0) / volumes.sum()


def reduced_volume(area, volume):
    """v = 6 sqrt(pi) V / A^(3/2): 1 for a sphere."""
    return 6.0 * math.sqrt(math.pi) * volume / area ** 1.5 if area > 0 else float("nan")


def edges(triangles):
    """Every directed edge of every triangle, (3m,2)."""
    return np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])


def boundary_edge_count(triangles):
    """Edges that belong to one triangle only: 0 for a closed surface."""
    e = np.sort(edges(triangles), axis=1)
    _, counts = np.unique(e, axis=0, return_counts=True)
    return int((counts == 1).sum())


def is_closed(triangles):
    return len(triangles) > 0 and boundary_edge_count(triangles) == 0


def principal_frame(x):
    """Centroid and principal directions of the vertex cloud, largest variance first."""
    c = x.mean(axis=0)
    _, vecs = np.linalg.eigh(np.cov((x - c).T))
    vecs = vecs[:, ::-1]
    if np.linalg.det(vecs) < 0:
        vecs[:, 2] = -vecs[:, 2]                          # keep a right-handed frame
    return c, vecs


def principal_semi_axes(x):
    """Half the extents of the vertex cloud along its principal directions (nm),
    descending, and the vertices in that frame (columns in the same order)."""
    c, vecs = principal_frame(x)
    y = (x - c) @ vecs
    semi = 0.5 * (y.max(axis=0) - y.min(axis=0))
    order = np.argsort(semi)[::-1]                        # variance and extent orders may differ
    return semi[order], y[:, order]


def classify(vertices, triangles):
    """A rough shape label and the principal semi-axes a1 >= a2 >= a3.

    open patch   the mesh has boundary edges: not a vesicle, no volume to speak of
    sphere       a1/a3 < 1.05
    prolate      elongation dominates: a1/a2 > a2/a3; "(triaxial)" appended when a2/a3 > 1.1
    oblate       flattening dominates: a2/a3 >= a1/a2; "(triaxial)" appended when a1/a2 > 1.1
    discocyte    oblate with a dimple (> 5% of the thickness) on both faces at the axis,
                 the membrane crossing the axis near the mid-plane
    stomatocyte  oblate with a one-sided dimple, or crossing the axis off the mid-plane
                 by more than 20% of the thickness (a cup)
    Heuristics for a quick label: read the semi-axes and look at the picture."""
    semi, y = principal_semi_axes(vertices)
    if not is_closed(triangles):
        return "open patch", semi
    a1, a2, a3 = semi
    if a1 / a3 < 1.05:
        return "sphere", semi
    if a1 / a2 > a2 / a3:
        return "prolate" + (" (triaxial)" if a2 / a3 > 1.1 else ""), semi
    triaxial = " (triaxial)" if a1 / a2 > 1.1 else ""
    # the axis of a flattened shape is its shortest principal direction (z here)
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


def vertex_edge_lengths(vertices, triangles):
    """Mean length of the edges at each vertex (nm); interior edges count twice, once per
    triangle, which weighs every edge alike on a closed mesh."""
    e = edges(triangles)
    length = np.linalg.norm(vertices[e[:, 0]] - vertices[e[:, 1]], axis=1)
    total = np.zeros(len(vertices))
    count = np.zeros(len(vertices))
    for k in (0, 1):
        np.add.at(total, e[:, k], length)
        np.add.at(count, e[:, k], 1)
    return total / np.maximum(count, 1)


def radius_of_gyration(filaments, keep=None, per_length=False):
    """Rg (nm) of the beads of the filaments selected by the boolean mask `keep` (all by
    default), and the number of beads; NaN without beads. With per_length the cylinders'
    midpoints are weighted by their lengths (exact length weighting) instead of counting
    every bead once."""
    polylines = filaments.polylines
    if keep is not None:
        polylines = [p for p, k in zip(polylines, keep) if k]
    beads = sum(len(p) for p in polylines)
    if beads == 0:
        return float("nan"), 0
    if per_length:
        points = np.concatenate([0.5 * (p[1:] + p[:-1]) for p in polylines])
        weights = np.concatenate([np.linalg.norm(p[1:] - p[:-1], axis=1) for p in polylines])
    else:
        points = np.concatenate(polylines)
        weights = np.ones(len(points))
    c = (points * weights[:, None]).sum(axis=0) / weights.sum()
    return float(np.sqrt((weights * ((points - c) ** 2).sum(axis=1)).sum() / weights.sum())), beads
