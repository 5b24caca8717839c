"""Render every snapshot of a run to an MP4 (ffmpeg), or to a PNG montage.

Membranes are coloured by mean curvature (red concave, blue convex) on one colour scale
for the whole run; filaments are drawn as line segments with cross-linkers green, motors
red and branch points orange; a run with both shows both. Every frame has the same axes
(the extent of the whole run at equal scale), so motion reads as motion. Frames are
PNGs rendered with matplotlib in a temporary folder and encoded with
`ffmpeg -c:v libx264 -pix_fmt yuv420p` (frame sizes padded to even numbers, as libx264
needs). Without ffmpeg, or with --montage, it writes a grid of snapshots to a PNG.

  movie OUT                       -> OUT/movie.mp4
  movie OUT --fps 5 -o shrink.mp4
  movie OUT --montage             -> OUT/movie.png (at most 25 snapshots, evenly spaced)
"""

import math
import os
import shutil
import subprocess
import tempfile

import numpy as np

from .. import geometry, plotting
from ..errors import CortexError
from . import common

HELP = "render a run to MP4 (ffmpeg) or a PNG montage"

# A montage keeps this many snapshots at most (evenly spaced, first and last included).
MONTAGE_PANELS = 25


def add_arguments(p):
    common.add_outdirs(p, many=False)
    common.add_out(p, "MP4 to write (default OUTDIR/movie.mp4; a montage is written as .png)", image=False)
    common.add_snapshot(p, "all")
    common.add_membrane(p)
    common.add_figure(p, "5", 100)
    p.add_argument("--fps", type=common.positive_float, default=10.0, help="frames per second (default 10)")
    p.add_argument("--montage", action="store_true", help="write a PNG grid of snapshots instead of an MP4")
    p.add_argument("--clim", type=common.positive_float,
                   help="colour limit |H| in 1/nm (default: the largest 99th percentile of |H| of a snapshot)")
    p.add_argument("--cmap", default="RdBu", help="diverging colormap, low = red (default RdBu)")
    p.add_argument("--elev", type=common.finite_float, default=20.0, help="view elevation in degrees (default 20)")
    p.add_argument("--azim", type=common.finite_float, default=-60.0, help="view azimuth in degrees (default -60)")
    p.add_argument("--cutaway", action="store_true",
                   help="leave out the near half of each membrane (the triangles between its centre and "
                        "the viewer), to see filaments inside a vesicle")
    p.add_argument("--columns", type=common.positive_int,
                   help="panels per row of a montage (default: a square grid); 3 snapshots of a long "
                        "shape read best in one row")
    p.add_argument("--zoom", type=common.positive_float, default=1.25,
                   help="3D axes zoom (default 1.25; below 1 when a long shape leaves the frame)")


class Scene:
    """What stays fixed over the frames: the snapshots, the membranes drawn, the axes
    and the colour scale, found in one pass over the run before drawing. Snapshots are
    opened afresh for each pass, so no more than one is held in memory."""

    def __init__(self, run, indices, args):
        self.run = run
        self.indices = indices
        self.membrane = args.membrane
        corners, limits = [], []          # per snapshot: extents of what is drawn, colour limit
        for s in map(run.snapshot, indices):
            membranes = self.membranes(s)
            points = [m.vertices for m in membranes]
            if s.filaments is not None:
                points += [s.filaments.beads, s.filaments.linkers, s.filaments.motors]
            if points:
                corners.append(np.stack(plotting.bounds(points, pad=0.0)))
            if membranes:
                limits.append(plotting.curvature_limit(membranes))
        if not corners:
            raise CortexError(f"{run.trajectory_path}: no membranes or filaments to draw")
        self.lo, self.hi = plotting.bounds(corners)
        self.has_membranes = bool(limits)
        self.limit = args.clim or max(limits, default=1.0)
        self.norm = plotting.curvature_norm(self.limit)
        self.cmap = plotting.pyplot().get_cmap(args.cmap)
        self.zoom = args.zoom
        self.view = (args.elev, args.azim)
        self.cutaway = args.cutaway

    def membranes(self, snapshot):
        if not snapshot.membranes:
            return []
        return common.membranes_of(snapshot, self.membrane)

    def draw(self, ax, index, separator):
        """Snapshot `index` of the run into a 3D axes, titled with its time, reduced
        volumes and counts joined by `separator`."""
        snapshot = self.run.snapshot(index)
        parts = [f"t = {snapshot.time:.4g} s"]
        for m in self.membranes(snapshot):
            hide = plotting.facing_half(m.vertices, m.triangles, *self.view) if self.cutaway else None
            plotting.add_membrane(ax, m.vertices, m, self.norm, self.cmap, hide=hide)
            if geometry.is_closed(m.triangles):
                parts.append(f"v = {geometry.reduced_volume(*geometry.area_volume(m.vertices, m.triangles)):.3f}")
        f = snapshot.filaments
        if f is not None:
            plotting.add_filaments(ax, f)
            parts.append(f"{len(f)} filaments, {len(f.linkers)} linkers, {len(f.motors)} motors")
        plotting.set_limits(ax, self.lo, self.hi, zoom=self.zoom)
        ax.view_init(*self.view)
        ax.set_axis_off()
        ax.set_title(separator.join(parts), fontsize=8)

    def add_colour_bar(self, fig):
        """The curvature colour bar at the right of a figure with membranes; returns the
        right edge left for the 3D axes (figure fraction)."""
        if not self.has_membranes:
            return 1.0
        plotting.curvature_colorbar(fig, self.limit, self.cmap, fig.add_axes([0.86, 0.25, 0.025, 0.5]))
        return 0.84


def write_frames(scene, folder, args):
    """One PNG per snapshot, frame_00000.png onwards."""
    plt = plotting.pyplot()
    w, h = args.size
    fig = plt.figure(figsize=(w, h))
    try:
        for k, i in enumerate(scene.indices):
            fig.clf()
            right = scene.add_colour_bar(fig)
            scene.draw(fig.add_axes([0.0, 0.0, right, 0.95], projection="3d"), i, ", ")
            fig.savefig(os.path.join(folder, f"frame_{k:05d}.png"), dpi=args.dpi)
    finally:
        plt.close(fig)


def encode(ffmpeg, folder, fps, out):
    command = [ffmpeg, "-y", "-loglevel", "error", "-framerate", f"{fps:g}",
               "-i", os.path.join(folder, "frame_%05d.png"),
               "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", out]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no message"])[-1]
        raise CortexError(f"{out}: ffmpeg failed ({last})")


def montage(scene, out, args):
    n = len(scene.indices)
    keep = [scene.indices[k] for k in sorted(set(np.linspace(0, n - 1, min(n, MONTAGE_PANELS)).round().astype(int)))]
    ncols = min(args.columns or math.ceil(math.sqrt(len(keep))), len(keep))
    nrows = math.ceil(len(keep) / ncols)
    w, h = args.size
    height = h * nrows * 0.6
    fig = plotting.pyplot().figure(figsize=(w * ncols * 0.6, height))
    right = scene.add_colour_bar(fig)
    # Half an inch at the top holds the first row's three-line titles.
    fig.subplots_adjust(left=0.0, right=right, bottom=0.0, top=1.0 - 0.5 / height, wspace=0.0, hspace=0.15)
    for k, i in enumerate(keep):
        scene.draw(fig.add_subplot(nrows, ncols, k + 1, projection="3d"), i, "\n")
    plotting.save(fig, out, args.dpi)
    return len(keep)


def run(args):
    r = common.open_run(args.outdir)
    scene = Scene(r, common.snapshot_indices(r, args.snapshot), args)
    out = args.out or common.default_out(r, "movie.mp4")
    ffmpeg = shutil.which("ffmpeg")
    if args.montage or ffmpeg is None:
        png = os.path.splitext(out)[0] + ".png"
        panels = montage(scene, png, args)
        reason = "--montage" if args.montage else "ffmpeg not found"
        print(f"{reason}: wrote a montage of {panels} of {len(scene.indices)} snapshots")
        common.wrote(png)
        return 0
    with tempfile.TemporaryDirectory(prefix="cortex_movie_") as folder:
        write_frames(scene, folder, args)
        encode(ffmpeg, folder, args.fps, out)
    print(f"{len(scene.indices)} frames at {args.fps:g} fps")
    common.wrote(out)
    return 0
