"""Phase separation of membrane proteins (thesis fig. 3.3): the distribution of the
area fraction phi = n A_p / |C| over the dual cells of a membrane, pooled over the
snapshots from --from on and weighted by cell area (the chance that a point of the
membrane sees that phi), for each run; A_p is the species' footprint and the pair
attraction's height h is read from each run's own config. A run counts as phase
separated when most copies sit in dense cells (phi >= 0.5; an ideal gas at the fig. 3.3
coverage puts ~10% there): an order parameter that the histogram's bins, which alias
the whole copies per cell, cannot fake. The onset is the smallest h from which every
run is separated.

  llps OUT                                     table
  llps SWEEP/members/* -o llps.png --from 0.11 the weakest and strongest run's last snapshot,
                                               histograms and the map over h (fig. 3.3a-d)
"""

import tomllib

import numpy as np

from .. import plotting
from ..errors import CortexError
from . import common

HELP = "area-fraction distributions of interacting membrane species over the pair attraction (table, PNG)"


def add_arguments(p):
    common.add_outdirs(p, many=True)
    common.add_out(p, "PNG to write (no plot without it)")
    common.add_figure(p, "14,3.6", 100)
    common.add_membrane(p)
    p.add_argument("--species", help="membrane species (default: the membrane's only one)")
    p.add_argument("--from", dest="start", type=common.finite_float, help="pool snapshots from this time (s) [a fifth of the run]")
    p.add_argument("--bins", type=common.positive_int, default=6, help="bins of phi over [0, 1] [6]")
    p.add_argument("--labels", metavar="LIST", help="comma-separated labels, one per run [h]")
    p.add_argument("--csv", metavar="FILE", help="also write the distributions as CSV (run column first)")
    p.add_argument("--title", help="figure title")


def species_config(run, membrane, species):
    """(footprint nm^2, interaction height k_BT or 0) of `species` on `membrane`, from the run's config."""
    if run.config is None:
        raise CortexError(f"{run.trajectory_path}: no config stored (a run older than this command)")
    for m in tomllib.loads(run.config).get("membrane", []):
        if m.get("name") != membrane:
            continue
        for s in m.get("species", []):
            if s.get("name") == species:
                footprint = s.get("footprint", 0.0)
                if not footprint > 0.0:
                    raise CortexError(f"{run.trajectory_path}: species '{species}' has no footprint: "
                                      "its area fraction is undefined")
                return footprint, s.get("interaction", {}).get("height", 0.0)
    raise CortexError(f"{run.trajectory_path}: species '{species}' of membrane '{membrane}' not in the stored config")


def distribution(outdir, membrane_name, species_name, start, bins):
    """Per run: h, the area-weighted histogram of phi (sums to 1), its summary numbers."""
    run = common.open_run(outdir)
    membrane = common.membranes_of(run.snapshot(0), membrane_name)[0]
    species = common.species_of(membrane, species_name, run.trajectory_path)
    footprint, height = species_config(run, membrane.name, species)
    snapshots = list(run.snapshots())
    if start is None:
        start = 0.2 * snapshots[-1].time
    phi, weight, copies = [], [], []
    last = None
    for s in snapshots:
        m = s.membranes.get(membrane.name)
        if m is None or s.time < start - 1e-12:
            continue
        areas = m.cell_areas()
        n = m.species[species].astype(float)
        phi.append(n * footprint / areas)
        weight.append(areas)
        copies.append(n)
        last = (s.time, m, phi[-1])
    if not phi:
        raise CortexError(f"{run.trajectory_path}: no snapshot at or after t = {start:g} s")
    used = len(phi)
    phi, weight, copies = np.concatenate(phi), np.concatenate(weight), np.concatenate(copies)
    hist, edges = np.histogram(np.minimum(phi, 1.0), bins=bins, range=(0.0, 1.0), weights=weight)
    hist = hist / hist.sum()
    centres = 0.5 * (edges[:-1] + edges[1:])
    dense = phi >= 0.5
    return {
        "height": height,
        "snapshots": used,
        "start": start,
        "mean": float(np.sum(phi * weight) / np.sum(weight)),
        "dense_area": float(np.sum(weight[dense]) / np.sum(weight)),
        "dense_copies": float(np.sum(copies[dense]) / max(np.sum(copies), 1.0)),
        "separated": bool(np.sum(copies[dense]) > 0.5 * np.sum(copies)),
        "hist": hist,
        "centres": centres,
        "last": last,  # time, membrane, phi per vertex of the last snapshot used
    }


def onset(results):
    """The smallest h from which every run (ordered by h) is phase separated, or None."""
    ordered = sorted(results, key=lambda r: r["height"])
    for i, r in enumerate(ordered):
        if all(o["separated"] for o in ordered[i:]):
            return r["height"]
    return None


def run(args):
    results = [distribution(d, args.membrane, args.species, args.start, args.bins) for d in args.outdir]
    labels = (common.run_labels(args) if args.labels
              else [f"h = {r['height']:g} kT" for r in results])
    # Each run is pooled over its own snapshots (its --from default is a fifth of its
    # own length, and runs may have stopped at different times): a column per run.
    print("# area fraction phi = n A_p / |C|, area-weighted, pooled over each run's snapshots from t = 'from (s)' on")
    print(f"{'run':>16} {'h (kT)':>7} {'mean phi':>9} {'area phi>=0.5':>14} {'copies there':>13} {'separated':>10} "
          f"{'snapshots':>9} {'from (s)':>9}")
    for label, r in zip(labels, results):
        print(f"{label:>16} {r['height']:7.3f} {r['mean']:9.3f} {r['dense_area']:14.3f} {r['dense_copies']:13.3f} "
              f"{'yes' if r['separated'] else 'no':>10} {r['snapshots']:9d} {r['start']:9.4g}")
    h0 = onset(results)
    print("onset of phase separation: " + (f"h = {h0:g} kT" if h0 is not None else "none of these runs"))
    if args.csv:
        columns = ["height_kT", "phi", "probability"]
        tables = [[[r["height"], c, p] for c, p in zip(r["centres"], r["hist"])] for r in results]
        common.write_tables_csv(args.csv, columns, labels, tables)
    if args.out:
        plot(args, labels, results)
    return 0


def draw_map(ax, result, label):
    """phi per vertex of a run's last snapshot, seen along the coordinate axis in which
    the membrane is thinnest (a flat patch from above; fig. 3.3a, b)."""
    time, membrane, phi = result["last"]
    first, second = sorted(np.argsort(np.ptp(membrane.vertices, axis=0))[1:])
    xy = membrane.vertices[:, [first, second]]
    image = ax.tripcolor(xy[:, 0], xy[:, 1], membrane.triangles, np.minimum(phi, 1.0), shading="gouraud",
                         cmap="viridis", vmin=0.0, vmax=1.0)
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title(f"{label}, t = {time:.3g} s", fontsize=8)
    return image


def plot(args, labels, results):
    plt = plotting.pyplot()
    from matplotlib.colors import LogNorm  # with pyplot: reading runs needs no matplotlib

    heights = [r["height"] for r in results]
    weakest, strongest = int(np.argmin(heights)), int(np.argmax(heights))
    shown = [weakest] if weakest == strongest else [weakest, strongest]
    fig, axes = plt.subplots(1, 2 + len(shown), figsize=args.size,
                             gridspec_kw={"width_ratios": [0.8] * len(shown) + [1.0, 1.0]})
    for k, i in enumerate(shown):
        image = draw_map(axes[k], results[i], labels[i])
    fig.colorbar(image, ax=axes[len(shown) - 1], shrink=0.7, label=r"area fraction $\phi_p$")
    ax, bx = axes[len(shown)], axes[len(shown) + 1]
    cmap = plt.get_cmap("viridis")
    span = (max(heights) - min(heights)) or 1.0
    for label, r in zip(labels, results):
        ax.semilogy(r["centres"], np.maximum(r["hist"], 1e-5), "o-", ms=3,
                    color=cmap((r["height"] - min(heights)) / span), label=label)
    ax.set_xlabel(r"area fraction $\phi_p$")
    ax.set_ylabel("probability (area-weighted)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    order = np.argsort(heights)
    grid = np.array([results[i]["hist"] for i in order]).T
    image = bx.imshow(np.maximum(grid, 1e-4), origin="lower", aspect="auto", cmap="magma",
                      norm=LogNorm(vmin=1e-3, vmax=1.0), extent=[-0.5, len(order) - 0.5, 0.0, 1.0])
    bx.set_xticks(range(len(order)))
    bx.set_xticklabels([f"{heights[i]:g}" for i in order], rotation=90, fontsize=7)
    bx.set_xlabel(r"attraction height $h$ ($k_BT$)")
    bx.set_ylabel(r"area fraction $\phi_p$")
    fig.colorbar(image, ax=bx, label="probability")
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    plotting.save(fig, args.out, args.dpi)
    common.wrote(args.out)
