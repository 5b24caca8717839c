"""Plain-text descriptions of a snapshot's parts, for `info` and `membrane --info`."""

import numpy as np

from . import geometry


def membrane_lines(snapshot, membrane):
    """Size, area, volume and reduced volume (closed meshes only), semi-axes, shape class."""
    x, tri = membrane.vertices, membrane.triangles
    area, volume = geometry.area_volume(x, tri)
    shape, semi = geometry.classify(x, tri)
    lines = [f"snapshot {snapshot.name}  t = {snapshot.time:.6g} s  membrane '{membrane.name}'  "
             f"{len(x)} vertices  {len(tri)} triangles"]
    if geometry.is_closed(tri):
        lines.append(f"  area {area:.6g} nm^2  volume {volume:.6g} nm^3  "
                     f"reduced volume {geometry.reduced_volume(area, volume):.4f}")
    else:
        lines.append(f"  area {area:.6g} nm^2  open: {geometry.boundary_edge_count(tri)} boundary edges, "
                     "no enclosed volume")
    lines.append(f"  principal semi-axes {semi[0]:.1f} {semi[1]:.1f} {semi[2]:.1f} nm  shape class: {shape}")
    if membrane.mean_curvature is not None and len(membrane.mean_curvature):
        h = membrane.mean_curvature
        lines.append(f"  mean curvature {h.min():.4g} .. {h.max():.4g} 1/nm")
    if membrane.species:
        # Membrane species: copies, and the mean and largest density over the vertices' cells.
        cells = membrane.cell_areas()
        parts = []
        for name, copies in membrane.species.items():
            density = copies / cells * 1e6
            parts.append(f"{name} {int(copies.sum())} (mean {copies.sum() / cells.sum() * 1e6:.4g}, "
                         f"max {density.max():.4g} /um^2)")
        lines.append("  species: " + ", ".join(parts))
    return lines


def filament_lines(snapshot, filaments):
    rg, _ = geometry.radius_of_gyration(filaments)
    return [f"snapshot {snapshot.name}  t = {snapshot.time:.6g} s  {len(filaments)} filaments  "
            f"{len(filaments.beads)} beads  total length {filaments.lengths.sum():.6g} nm  Rg {rg:.1f} nm",
            f"  {len(filaments.linkers)} linkers  {len(filaments.motors)} motors  "
            f"{len(filaments.branch_points)} branch points"]


def species_lines(snapshot, species):
    return [f"snapshot {snapshot.name}  t = {snapshot.time:.6g} s  species (copies, grid "
            f"{'x'.join(map(str, next(iter(species.values())).shape))}): "
            + "  ".join(f"{name} {int(np.sum(a))}" for name, a in species.items())]
