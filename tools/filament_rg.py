#!/usr/bin/python3
"""Radius of gyration of a cortex run's filament beads over time.

Reads OUTDIR/trajectory.h5 (layout: docs/output.md):
  /snapshots/NNNNNN                 attrs: time (s)
  /snapshots/NNNNNN/filaments/beads    (k,3) nm, all filaments' beads in order
  /snapshots/NNNNNN/filaments/offsets  (f+1) filament i owns beads offsets[i]..offsets[i+1]-1
  /snapshots/NNNNNN/filaments/types    (f)   filament type index (for --type)
  /snapshots/NNNNNN/filaments/linkers, motors, branch_points  (n,2,3), (n,2,3), (b,3)

Rg(t) = sqrt(mean_i |r_i - r_mean|^2) over the beads of the selected filaments (all
beads count equally; with 40-monomer cylinders the beads are ~108 nm apart, so this
is the length-weighted Rg up to the half-cylinders at the ends). With --per-length the
cylinders' midpoints are weighted by their lengths instead (exact length weighting).

For every run it prints one table row per snapshot (time, Rg, Rg/Rg(0), filaments,
beads, bound linkers, bound motors, branch points) and a last line with the relative
change Rg(end)/Rg(0) - 1. With -o it writes a PNG: Rg(t) of every run on one axis, and
with --bound a second panel with the bound linker and motor counts.

Usage:
  filament_rg.py OUT                              # table only
  filament_rg.py OUT -o rg.png                    # table + plot
  filament_rg.py OUT1 OUT2 OUT3 --labels "seed 1,seed 2,seed 3" --bound -o rg.png
  filament_rg.py OUT --normalize -o rg.png        # plot Rg/Rg(0)
  filament_rg.py OUT --type 0                     # only filaments of type index 0
  filament_rg.py OUT --csv rg.csv                 # the table as CSV too

Exit code 2 with a one-line message on a missing file or a run without filaments.
Needs numpy, h5py and matplotlib (Debian: /usr/bin/python3).
"""

import argparse
import os
import sys

import numpy as np


def die(msg):
    print(f"filament_rg.py: {msg}", file=sys.stderr)
    sys.exit(2)


def rg_of(beads, offsets, types, type_sel, per_length):
    """Radius of gyration (nm) of the selected filaments' beads; nan if none."""
    offsets = np.asarray(offsets, dtype=np.int64)
    nfil = len(offsets) - 1
    keep = np.ones(nfil, dtype=bool)
    if type_sel is not None and types is not None and len(types) == nfil:
        keep = np.asarray(types) == type_sel
    if not keep.any():
        return float("nan"), 0, 0
    if not per_length:
        idx = np.concatenate([np.arange(offsets[i], offsets[i + 1]) for i in np.flatnonzero(keep)])
        pts = beads[idx]
        c = pts.mean(axis=0)
        return float(np.sqrt(((pts - c) ** 2).sum(axis=1).mean())), int(keep.sum()), len(idx)
    mids, w = [], []
    nb = 0
    for i in np.flatnonzero(keep):
        p = beads[offsets[i]:offsets[i + 1]]
        nb += len(p)
        mids.append(0.5 * (p[1:] + p[:-1]))
        w.append(np.linalg.norm(p[1:] - p[:-1], axis=1))
    mids = np.concatenate(mids)
    w = np.concatenate(w)
    c = (mids * w[:, None]).sum(axis=0) / w.sum()
    return float(np.sqrt((w * ((mids - c) ** 2).sum(axis=1)).sum() / w.sum())), int(keep.sum()), nb


def read_run(outdir, type_sel, per_length):
    import h5py

    path = outdir if outdir.endswith(".h5") else os.path.join(outdir, "trajectory.h5")
    if not os.path.isfile(path):
        die(f"{path}: no such file")
    rows = []
    with h5py.File(path, "r") as f:
        if "snapshots" not in f:
            die(f"{path}: no /snapshots group")
        for name in sorted(f["snapshots"].keys()):
            g = f["snapshots"][name]
            if "filaments" not in g:
                continue
            fg = g["filaments"]
            beads = fg["beads"][()]
            offsets = fg["offsets"][()]
            types = fg["types"][()] if "types" in fg else None
            if len(offsets) < 2:
                continue
            rg, nfil, nb = rg_of(beads, offsets, types, type_sel, per_length)
            nl = fg["linkers"].shape[0] if "linkers" in fg else 0
            nm = fg["motors"].shape[0] if "motors" in fg else 0
            nbp = fg["branch_points"].shape[0] if "branch_points" in fg else 0
            rows.append((float(g.attrs.get("time", np.nan)), rg, nfil, nb, nl, nm, nbp))
    if not rows:
        die(f"{path}: no snapshot with filaments")
    return np.array(rows, dtype=float)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__[__doc__.index("Usage:"):])
    ap.add_argument("outdirs", nargs="+", help="run output folders (or trajectory.h5 files)")
    ap.add_argument("-o", "--out", help="PNG to write (no plot without it)")
    ap.add_argument("--labels", help="comma-separated legend labels, one per run")
    ap.add_argument("--bound", action="store_true", help="second panel: bound linkers and motors")
    ap.add_argument("--normalize", action="store_true", help="plot Rg/Rg(0) instead of Rg")
    ap.add_argument("--type", type=int, default=None, help="only filaments of this type index")
    ap.add_argument("--per-length", action="store_true",
                    help="weight cylinder midpoints by cylinder length instead of beads equally")
    ap.add_argument("--csv", help="also write the table(s) as CSV (run column added)")
    ap.add_argument("--title", default=None)
    ap.add_argument("--dpi", type=int, default=100)
    ap.add_argument("--size", default="6,4", help="figure size in inches per panel, W,H")
    ap.add_argument("--quiet", action="store_true", help="only the summary line per run")
    a = ap.parse_args()

    labels = a.labels.split(",") if a.labels else [os.path.basename(os.path.normpath(d)) for d in a.outdirs]
    if len(labels) != len(a.outdirs):
        die(f"--labels has {len(labels)} entries for {len(a.outdirs)} runs")

    runs = [read_run(d, a.type, a.per_length) for d in a.outdirs]
    csv_lines = ["run,time_s,rg_nm,rg_rel,filaments,beads,linkers,motors,branch_points"]
    for lab, r in zip(labels, runs):
        rg0 = r[0, 1]
        if not a.quiet:
            print(f"# {lab}")
            print(f"{'t (s)':>8} {'Rg (nm)':>9} {'Rg/Rg0':>7} {'fil':>5} {'beads':>6} "
                  f"{'linkers':>7} {'motors':>6} {'branch':>6}")
            for t, rg, nf, nb, nl, nm, nbp in r:
                print(f"{t:8.3f} {rg:9.1f} {rg / rg0:7.3f} {int(nf):5d} {int(nb):6d} "
                      f"{int(nl):7d} {int(nm):6d} {int(nbp):6d}")
        print(f"{lab}: Rg {rg0:.1f} -> {r[-1, 1]:.1f} nm over {r[-1, 0] - r[0, 0]:.2f} s "
              f"({100 * (r[-1, 1] / rg0 - 1):+.1f}%)")
        for t, rg, nf, nb, nl, nm, nbp in r:
            csv_lines.append(f"{lab},{t},{rg},{rg / rg0},{int(nf)},{int(nb)},{int(nl)},{int(nm)},{int(nbp)}")
    if a.csv:
        with open(a.csv, "w") as fh:
            fh.write("\n".join(csv_lines) + "\n")

    if not a.out:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    w, h = (float(x) for x in a.size.split(","))
    npan = 2 if a.bound else 1
    fig, axes = plt.subplots(1, npan, figsize=(w * npan, h), squeeze=False)
    ax = axes[0, 0]
    for i, (lab, r) in enumerate(zip(labels, runs)):
        y = r[:, 1] / r[0, 1] if a.normalize else r[:, 1]
        ax.plot(r[:, 0], y, "o-", ms=3, color=f"C{i}", label=lab)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("Rg / Rg(0)" if a.normalize else "radius of gyration of actin beads (nm)")
    ax.grid(alpha=0.3)
    if len(runs) > 1:
        ax.legend(fontsize=8)
    if a.bound:
        bx = axes[0, 1]
        for i, (lab, r) in enumerate(zip(labels, runs)):
            bx.plot(r[:, 0], r[:, 4], "-", color=f"C{i}", label=f"{lab} linkers" if len(runs) > 1 else "linkers")
            bx.plot(r[:, 0], r[:, 5], "--", color=f"C{i}", label=f"{lab} motors" if len(runs) > 1 else "motors")
        bx.set_xlabel("time (s)")
        bx.set_ylabel("bound count")
        bx.grid(alpha=0.3)
        bx.legend(fontsize=7)
    if a.title:
        fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.out, dpi=a.dpi)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
