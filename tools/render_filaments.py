#!/usr/bin/python3
"""Render the filaments of a cortex run with matplotlib 3D: first and last snapshot side by side.

Reads OUTDIR/trajectory.h5 (layout: docs/output.md):
  /snapshots/NNNNNN                       attrs: time (s)
  /snapshots/NNNNNN/filaments/beads          (k,3)   nm, all filaments' beads in order
  /snapshots/NNNNNN/filaments/offsets        (f+1)   filament i owns beads offsets[i]..offsets[i+1]-1
  /snapshots/NNNNNN/filaments/linkers        (n,2,3) nm, the two bound ends of each cross-linker
  /snapshots/NNNNNN/filaments/motors         (n,2,3) nm, the two bound ends of each motor
  /snapshots/NNNNNN/filaments/branch_points  (b,3)   nm, Arp2/3 branch sites

Filaments are drawn as grey-blue polylines (plus ends marked with a small dot when
--ends), cross-linkers as short green segments, motors as red segments, branch points as
orange markers. Every panel shares one set of axis limits (the union over the drawn
snapshots, or the box given by --box), drawn at equal scale on every axis, so a contraction
or a growth front reads directly. --wall draws a boundary wall as a grey plane.
Each panel's title gives the time, filament and bead counts, bound linkers/motors,
branch points, and the beads' radius of gyration.

Usage:
  render_filaments.py OUT                              # first + last -> OUT/filaments.png
  render_filaments.py OUT -o net.png --snapshots 0,5,last
  render_filaments.py OUT -o net.png --box 0,0,0,2000,2000,2000 --elev 20 --azim -60
  render_filaments.py OUT -o net.png --views 2          # oblique view + view along an axis
  render_filaments.py OUT -o net.png --no-linkers      # filaments and motors only
  render_filaments.py OUT -o net.png --wall z=1000 --ends   # show a boundary wall and plus ends

Exit code 2 with a one-line message on a missing file or snapshot.
Needs numpy, h5py and matplotlib (Debian: /usr/bin/python3).
"""

import argparse
import os
import sys

import numpy as np


def die(msg):
    print(f"render_filaments.py: {msg}", file=sys.stderr)
    sys.exit(2)


def load(path, which):
    import h5py

    with h5py.File(path, "r") as f:
        if "snapshots" not in f:
            die(f"{path}: no /snapshots group")
        names = sorted(f["snapshots"].keys())
        out = []
        for w in which:
            if w == "first":
                i = 0
            elif w == "last":
                i = len(names) - 1
            else:
                try:
                    i = int(w)
                except ValueError:
                    die(f"bad snapshot '{w}' (N, first or last)")
                if i < 0:
                    i += len(names)
            if not 0 <= i < len(names):
                die(f"{path}: no snapshot {w} ({len(names)} snapshots)")
            g = f["snapshots"][names[i]]
            if "filaments" not in g:
                die(f"{path}: snapshot {names[i]} has no filaments group")
            fg = g["filaments"]

            def get(k, shape):
                return fg[k][()] if k in fg else np.zeros(shape)

            out.append(dict(
                name=names[i],
                time=float(g.attrs.get("time", np.nan)),
                beads=fg["beads"][()],
                offsets=fg["offsets"][()].astype(np.int64),
                linkers=get("linkers", (0, 2, 3)),
                motors=get("motors", (0, 2, 3)),
                branch=get("branch_points", (0, 3)),
            ))
        return out


def segments_3d(ax, pairs, color, lw, alpha):
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    if len(pairs):
        ax.add_collection3d(Line3DCollection(np.asarray(pairs), colors=color, linewidths=lw, alpha=alpha))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__[__doc__.index("Usage:"):])
    ap.add_argument("outdir", help="run output folder (or its trajectory.h5)")
    ap.add_argument("-o", "--out", help="PNG (default OUTDIR/filaments.png)")
    ap.add_argument("--snapshots", default="first,last", help="comma list: N, first, last (default first,last)")
    ap.add_argument("--box", help="axis limits xmin,ymin,zmin,xmax,ymax,zmax in nm (default: data extent)")
    ap.add_argument("--views", type=int, default=1, choices=(1, 2), help="1: oblique; 2: oblique + along --axis")
    ap.add_argument("--axis", default="z", choices=("x", "y", "z"), help="viewing axis of the second view")
    ap.add_argument("--elev", type=float, default=22.0)
    ap.add_argument("--azim", type=float, default=-55.0)
    ap.add_argument("--wall", action="append", help="draw a translucent wall plane AXIS=VALUE in nm (repeatable)")
    ap.add_argument("--no-linkers", action="store_true")
    ap.add_argument("--no-motors", action="store_true")
    ap.add_argument("--ends", action="store_true", help="mark plus ends with dots")
    ap.add_argument("--lw", type=float, default=0.8, help="filament line width")
    ap.add_argument("--size", default="4.2", help="panel size in inches: S or W,H")
    ap.add_argument("--zoom", type=float, default=1.2, help="3D axes zoom (matplotlib >= 3.6)")
    ap.add_argument("--dpi", type=int, default=100)
    ap.add_argument("--title", default=None)
    a = ap.parse_args()

    path = a.outdir if a.outdir.endswith(".h5") else os.path.join(a.outdir, "trajectory.h5")
    if not os.path.isfile(path):
        die(f"{path}: no such file")
    snaps = load(path, [s.strip() for s in a.snapshots.split(",") if s.strip()])
    out = a.out or os.path.join(os.path.dirname(path), "filaments.png")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    if a.box:
        b = [float(x) for x in a.box.split(",")]
        if len(b) != 6:
            die("--box needs 6 numbers")
        lo, hi = np.array(b[:3]), np.array(b[3:])
    else:
        allp = np.concatenate([s["beads"] for s in snaps if len(s["beads"])] or [np.zeros((1, 3))])
        lo, hi = allp.min(axis=0), allp.max(axis=0)
        pad = 0.03 * (hi - lo).max()
        lo, hi = lo - pad, hi + pad
    lim = np.stack([lo, hi], axis=1)  # per-axis limits, drawn at equal scale (box aspect)
    walls = []
    for w in a.wall or []:
        try:
            ax_name, val = w.split("=")
            walls.append(("xyz".index(ax_name.strip()), float(val)))
        except ValueError:
            die(f"bad --wall '{w}' (AXIS=VALUE, e.g. z=1000)")

    views = [(a.elev, a.azim)]
    if a.views == 2:
        views.append({"x": (0, 0), "y": (0, -90), "z": (90, -90)}[a.axis])
    ncol, nrow = len(snaps), len(views)
    pw, ph = (float(x) for x in (a.size.split(",") * 2)[:2])
    fig = plt.figure(figsize=(pw * ncol, ph * nrow))
    for c, s in enumerate(snaps):
        beads, off = s["beads"], s["offsets"]
        polys = [beads[off[i]:off[i + 1]] for i in range(len(off) - 1)]
        fil_pairs = [np.stack([p[:-1], p[1:]], axis=1) for p in polys if len(p) > 1]
        fil_pairs = np.concatenate(fil_pairs) if fil_pairs else np.zeros((0, 2, 3))
        rg = float(np.sqrt(((beads - beads.mean(axis=0)) ** 2).sum(axis=1).mean())) if len(beads) else 0.0
        for r, (el, az) in enumerate(views):
            ax = fig.add_subplot(nrow, ncol, r * ncol + c + 1, projection="3d")
            segments_3d(ax, fil_pairs, "#3b5b92", a.lw, 0.85)
            if not a.no_linkers:
                segments_3d(ax, s["linkers"], "#2ca02c", 0.9, 0.8)
            if not a.no_motors:
                segments_3d(ax, s["motors"], "#d62728", 1.3, 0.9)
            if len(s["branch"]):
                bp = s["branch"]
                ax.scatter(bp[:, 0], bp[:, 1], bp[:, 2], s=10, c="#ff7f0e", depthshade=False)
            if a.ends and polys:
                pe = np.array([p[-1] for p in polys if len(p)])
                ax.scatter(pe[:, 0], pe[:, 1], pe[:, 2], s=3, c="k", depthshade=False)
            ax.set_xlim(*lim[0])
            ax.set_ylim(*lim[1])
            ax.set_zlim(*lim[2])
            for k, val in walls:
                o = [i for i in range(3) if i != k]
                u, v = np.meshgrid(lim[o[0]], lim[o[1]])
                xyz = [None] * 3
                xyz[k], xyz[o[0]], xyz[o[1]] = np.full_like(u, val), u, v
                ax.plot_surface(*xyz, color="0.5", alpha=0.15, shade=False)
            try:
                ax.set_box_aspect(tuple(lim[:, 1] - lim[:, 0]), zoom=a.zoom)
            except TypeError:  # matplotlib < 3.6: no zoom
                ax.set_box_aspect(tuple(lim[:, 1] - lim[:, 0]))
            except AttributeError:
                pass
            ax.view_init(elev=el, azim=az)
            ax.tick_params(labelsize=6, pad=0)
            ax.set_xlabel("x (nm)", fontsize=7, labelpad=-2)
            ax.set_ylabel("y (nm)", fontsize=7, labelpad=-2)
            ax.set_zlabel("z (nm)", fontsize=7, labelpad=-2)
            if r == 1:  # the axis we look along: no crowded ticks
                getattr(ax, f"set_{a.axis}ticklabels")([])
                getattr(ax, f"set_{a.axis}label")("")
            if r == 0:
                ax.set_title(f"t = {s['time']:.2f} s: {len(polys)} filaments, {len(beads)} beads\n"
                             f"{len(s['linkers'])} linkers, {len(s['motors'])} motors, "
                             f"{len(s['branch'])} branches, Rg = {rg:.0f} nm", fontsize=8)
    handles = [Line2D([], [], color="#3b5b92", lw=1.5, label="filament")]
    if not a.no_linkers and any(len(s["linkers"]) for s in snaps):
        handles.append(Line2D([], [], color="#2ca02c", lw=1.5, label="cross-linker"))
    if not a.no_motors and any(len(s["motors"]) for s in snaps):
        handles.append(Line2D([], [], color="#d62728", lw=1.5, label="motor"))
    if any(len(s["branch"]) for s in snaps):
        handles.append(Line2D([], [], color="#ff7f0e", marker="o", lw=0, label="Arp2/3 branch"))
    if a.ends:
        handles.append(Line2D([], [], color="k", marker="o", ms=3, lw=0, label="plus end"))
    fig.legend(handles=handles, loc="lower center", ncol=len(handles), fontsize=8, frameon=False)
    if a.title:
        fig.suptitle(a.title, fontsize=10)
    fig.subplots_adjust(left=0.02, right=0.98, top=0.9 if nrow > 1 else 0.8, bottom=0.07 if nrow > 1 else 0.12, wspace=0.05, hspace=0.05)
    fig.savefig(out, dpi=a.dpi)
    print(f"wrote {out} ({os.path.getsize(out) // 1024} KB)")


if __name__ == "__main__":
    main()
