"""Drawing shared by the commands: matplotlib without a display, membranes coloured by
mean curvature, filament networks as line segments, equal-scale 3D axes."""

import numpy as np

from .errors import CortexError

# Colours of the filament network's parts (filaments blue-grey, as in docs/images).
FILAMENT = "#3b5b92"
LINKER = "#2ca02c"
MOTOR = "#d62728"
BRANCH = "#ff7f0e"

# Light direction of the Lambert shading that lets a curvature-coloured mesh read as 3D.
LIGHT = np.array([-0.4, -0.5, 0.77]) / np.linalg.norm([-0.4, -0.5, 0.77])


def pyplot():
    """matplotlib.pyplot on the Agg backend (no display needed); imported on first use so
    that reading runs does not need matplotlib."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def image_formats():
    """File extensions savefig writes (png, pdf, svg, ...)."""
    from matplotlib.backend_bases import FigureCanvasBase
    return set(FigureCanvasBase.get_supported_filetypes())


def save(fig, path, dpi):
    """Write a figure and close it (figures stay alive in pyplot's registry otherwise)."""
    try:
        fig.savefig(path, dpi=dpi)
    except OSError as e:
        raise CortexError(f"{path}: cannot write ({e.strerror or e})") from None
    finally:
        pyplot().close(fig)


# ---------------------------------------------------------------- membranes

def face_curvature(membrane):
    """Mean curvature per triangle (mean of its vertices), or None without curvature."""
    if membrane.mean_curvature is None:
        return None
    return membrane.mean_curvature[membrane.triangles].mean(axis=1)


def curvature_limit(membranes):
    """A symmetric colour limit |H| (1/nm) for the membranes: the 99th percentile of the
    faces' |H|, so a few extreme faces do not wash out the picture."""
    values = [np.abs(v) for v in map(face_curvature, membranes) if v is not None and len(v)]
    limit = float(np.percentile(np.concatenate(values), 99)) if values else 0.0
    return limit if limit > 0 else 1.0


def curvature_norm(limit):
    from matplotlib import colors
    return colors.Normalize(vmin=-limit, vmax=limit)


def facing_half(vertices, triangles, elev, azim):
    """Mask of the triangles whose centroids lie on the viewer's side of the plane through
    the mesh's centre facing the view (elevation and azimuth in degrees, as matplotlib's
    view_init): dropping them cuts the near half away."""
    e, a = np.radians(elev), np.radians(azim)
    towards_viewer = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    centroids = vertices[triangles].mean(axis=1)
    return (centroids - vertices.mean(axis=0)) @ towards_viewer > 0


def add_membrane(ax, vertices, membrane, norm, cmap, edges=False, hide=None):
    """A membrane as shaded triangles coloured by mean curvature; `vertices` may be the
    membrane's own or the same points in another frame; `hide`: a mask of triangles to
    leave out."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    tri = membrane.triangles
    a, b, c = (vertices[tri[:, k]] for k in range(3))
    n = np.cross(b - a, c - a)
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    shade = 0.6 + 0.4 * np.abs(n @ LIGHT)
    values = face_curvature(membrane)
    if values is None:
        rgba = np.tile([0.75, 0.75, 0.75, 1.0], (len(tri), 1))
    else:
        rgba = np.array(cmap(norm(values)))
    rgba[:, :3] *= shade[:, None]
    if hide is not None:
        tri, rgba = tri[~hide], rgba[~hide]
    ax.add_collection3d(Poly3DCollection(vertices[tri], facecolors=rgba,
                                         edgecolors=(0, 0, 0, 0.25) if edges else "none",
                                         linewidths=0.2 if edges else 0.0))


def curvature_colorbar(fig, limit, cmap, cax=None):
    """Colour bar in 1/µm (the numbers read better than in 1/nm), in `cax` or beside
    every axes of the figure."""
    from matplotlib import colors
    sm = pyplot().cm.ScalarMappable(norm=colors.Normalize(-limit * 1e3, limit * 1e3), cmap=cmap)
    if cax is None:
        bar = fig.colorbar(sm, ax=fig.axes, shrink=0.7, pad=0.02, fraction=0.04)
    else:
        bar = fig.colorbar(sm, cax=cax)
    bar.set_label("mean curvature H (1/µm)\nred concave, blue convex", fontsize=7)
    bar.ax.tick_params(labelsize=6)


# ---------------------------------------------------------------- filaments

def add_segments(ax, segments, color, lw, alpha):
    from mpl_toolkits.mplot3d.art3d import Line3DCollection
    if len(segments):
        ax.add_collection3d(Line3DCollection(np.asarray(segments), colors=color, linewidths=lw, alpha=alpha))


def add_filaments(ax, filaments, linkers=True, motors=True, ends=False, lw=0.8):
    """Filaments as polylines, linkers green, motors red, branch points orange, plus
    ends black dots (ends=True)."""
    add_segments(ax, filaments.segments, FILAMENT, lw, 0.85)
    if linkers:
        add_segments(ax, filaments.linkers, LINKER, 0.9, 0.8)
    if motors:
        add_segments(ax, filaments.motors, MOTOR, 1.3, 0.9)
    if len(filaments.branch_points):
        bp = filaments.branch_points
        ax.scatter(bp[:, 0], bp[:, 1], bp[:, 2], s=10, c=BRANCH, depthshade=False)
    if ends and len(filaments):
        pe = filaments.beads[filaments.offsets[1:] - 1]
        ax.scatter(pe[:, 0], pe[:, 1], pe[:, 2], s=3, c="k", depthshade=False)


def filament_legend(fig, linkers, motors, branches, ends):
    """A legend naming only the parts that are drawn."""
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], color=FILAMENT, lw=1.5, label="filament")]
    if linkers:
        handles.append(Line2D([], [], color=LINKER, lw=1.5, label="cross-linker"))
    if motors:
        handles.append(Line2D([], [], color=MOTOR, lw=1.5, label="motor"))
    if branches:
        handles.append(Line2D([], [], color=BRANCH, marker="o", lw=0, label="Arp2/3 branch"))
    if ends:
        handles.append(Line2D([], [], color="k", marker="o", ms=3, lw=0, label="plus end"))
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8, frameon=False)


# --------------------------------------------------------------------- axes

def bounds(point_sets, pad=0.03):
    """Per-axis (lo, hi) enclosing every (n,3) array, padded by `pad` of the largest
    extent; a unit box around the origin when there are no points."""
    points = [p.reshape(-1, 3) for p in point_sets if p.size]
    if not points:
        return -np.ones(3), np.ones(3)
    lo = np.min([p.min(axis=0) for p in points], axis=0)
    hi = np.max([p.max(axis=0) for p in points], axis=0)
    margin = pad * max(float((hi - lo).max()), 1e-9)
    return lo - margin, hi + margin


def set_limits(ax, lo, hi, zoom=1.0):
    """Axis limits with one nm the same length on every axis."""
    for setter, a, b in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), lo, hi):
        setter(a, b)
    ax.set_box_aspect(tuple(np.maximum(hi - lo, 1e-9)), zoom=zoom)
