#!/usr/bin/env python3
"""Edge length against mean curvature in one snapshot of a cortex run.

Shows whether adaptive remeshing refined the mesh where the membrane is curved: each
vertex's mean incident edge length is binned by its |mean curvature| and compared with
the sizing rule L = sqrt(6 eps / k - 3 eps^2), clamped (k taken as |H|, exact on
spheres; the remesher uses the largest principal curvature, which is >= |H|).

usage: mesh_resolution.py OUTDIR [--snapshot N|last] [--membrane NAME]
                          [--mesh-size 60] [--min-size 15] [--max-size 120]
                          [--tolerance 0.5] [--out resolution.png]
"""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load(outdir, snapshot, membrane):
    path = outdir if outdir.endswith(".h5") else f"{outdir}/trajectory.h5"
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        sys.exit(f"mesh_resolution.py: cannot open {path}: {e}")
    names = sorted(f["snapshots"])
    key = names[-1] if snapshot == "last" else f"{int(snapshot):06d}"
    if key not in f["snapshots"]:
        sys.exit(f"mesh_resolution.py: {path} has no snapshot {snapshot}")
    group = f["snapshots"][key]["membranes"]
    name = membrane or sorted(group)[0]
    g = group[name]
    return g["vertices"][:], g["triangles"][:], g["mean_curvature"][:], f["snapshots"][key].attrs["time"]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("outdir")
    p.add_argument("--snapshot", default="last")
    p.add_argument("--membrane")
    p.add_argument("--mesh-size", type=float, default=60.0)
    p.add_argument("--min-size", type=float)
    p.add_argument("--max-size", type=float)
    p.add_argument("--tolerance", type=float)
    p.add_argument("--out", default="resolution.png")
    a = p.parse_args()
    lo = a.min_size or a.mesh_size / 4
    hi = a.max_size or 2 * a.mesh_size
    eps = a.tolerance or a.mesh_size / 120

    x, tri, H, time = load(a.outdir, a.snapshot, a.membrane)
    edges = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    length = np.linalg.norm(x[edges[:, 0]] - x[edges[:, 1]], axis=1)
    total = np.zeros(len(x))
    count = np.zeros(len(x))
    for k in (0, 1):
        np.add.at(total, edges[:, k], length)
        np.add.at(count, edges[:, k], 1)
    vertex_edge = total / count
    k = np.abs(H)

    bins = np.quantile(k, np.linspace(0, 1, 11))
    centers, means = [], []
    for b0, b1 in zip(bins[:-1], bins[1:]):
        sel = (k >= b0) & (k <= b1)
        centers.append(np.median(k[sel]))
        means.append(vertex_edge[sel].mean())
    kk = np.linspace(max(k.min(), 1e-6), k.max(), 200)
    rule = np.clip(np.minimum(np.sqrt(np.maximum(6 * eps / kk - 3 * eps**2, 0)), a.mesh_size), lo, hi)

    fig, ax = plt.subplots(figsize=(5.5, 3.6), dpi=90)
    ax.scatter(k * 1e3, vertex_edge, s=2, alpha=0.25, color="0.5", label="vertices")
    ax.plot(np.array(centers) * 1e3, means, "o-", color="C0", label="mean per decile of |H|")
    ax.plot(kk * 1e3, rule, "--", color="C3", label="sizing rule at k = |H|")
    ax.set_xlabel("|mean curvature| (1/µm)")
    ax.set_ylabel("mean incident edge length (nm)")
    ax.set_title(f"t = {time:.3g} s, {len(x)} vertices")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out)
    flat = vertex_edge[k <= np.quantile(k, 0.2)].mean()
    curved = vertex_edge[k >= np.quantile(k, 0.9)].mean()
    print(f"mean edge: flattest 20% of vertices {flat:.1f} nm, most curved 10% {curved:.1f} nm; wrote {a.out}")


if __name__ == "__main__":
    main()
