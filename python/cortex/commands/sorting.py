"""Curvature sorting of membrane proteins (thesis fig. 3.4): for every membrane with
species, its mean curvature and the density of each of its species, averaged over the
snapshots from --from on, against the dilute closed form of curvature sensing,
rho ∝ exp(-2 A_p kappa_eff (H^2 - 2 H H_p) / k_BT), kappa_eff = kappa_l kappa_p /
(kappa_l + kappa_p), read from the run's own config (species with a [curvature] table;
the config's temperature). Densities are relative to the least curved membrane's.

  sorting OUT                              table
  sorting OUT -o sorting.png --from 1.0    plot, averaging from t = 1 s
"""

import tomllib

import numpy as np

from .. import plotting
from ..errors import CortexError
from . import common

HELP = "density of curvature-sensing membrane species against curvature, with the closed form (table, PNG)"

BOLTZMANN = 1.380649e-2  # pN nm / K


def add_arguments(p):
    common.add_outdirs(p, many=False)
    common.add_out(p, "PNG to write (no plot without it)")
    common.add_figure(p, "5,3.6", 100)
    p.add_argument("--from", dest="start", type=common.finite_float, help="average snapshots from this time (s) [half the run]")
    p.add_argument("--title", help="figure title")


def sensing_of(config):
    """{species name: (A_p, kappa_p, H_p, kappa_l)} for curvature-sensing membrane species."""
    out = {}
    for m in config.get("membrane", []):
        kappa_l = m.get("bending_modulus")
        for s in m.get("species", []):
            c = s.get("curvature")
            if c is not None and isinstance(kappa_l, (int, float)):
                out[s["name"]] = (c["area"], c["bending_modulus"], c.get("spontaneous_curvature", 0.0), kappa_l)
    return out


def dilute_energy(H, area, kappa_p, H_p, kappa_l):
    """pN nm: 2 A_p kappa_eff (H^2 - 2 H H_p)."""
    kappa_eff = kappa_l * kappa_p / (kappa_l + kappa_p)
    return 2.0 * area * kappa_eff * (H * H - 2.0 * H * H_p)


def table(outdir, start):
    run = common.open_run(outdir)
    if run.config is None:
        raise CortexError(f"{run.trajectory_path}: no config stored (a run older than this command)")
    config = tomllib.loads(run.config)
    kT = BOLTZMANN * config.get("simulation", {}).get("temperature", 298.15)
    sensing = sensing_of(config)
    snapshots = list(run.snapshots())
    if start is None:
        start = 0.5 * snapshots[-1].time
    used = [s for s in snapshots if s.time >= start - 1e-12]
    if not used:
        raise CortexError(f"{run.trajectory_path}: no snapshot at or after t = {start:g} s")
    sums = {}
    for s in used:
        for name, m in s.membranes.items():
            areas = m.cell_areas()
            for species, copies in m.species.items():
                row = sums.setdefault((name, species), [0.0, 0.0, 0.0])
                row[0] += float(np.sum(areas * m.mean_curvature)) / float(np.sum(areas))
                row[1] += float(np.sum(copies)) / float(np.sum(areas))
                row[2] += 1.0
    if not sums:
        raise CortexError(f"{run.trajectory_path}: no membrane species")
    rows = []
    for (name, species), (h, rho, count) in sums.items():
        H, density = h / count, rho / count
        energy = dilute_energy(H, *sensing[species]) / kT if species in sensing else 0.0
        rows.append([name, species, H, density * 1e6, np.exp(-energy)])
    reference = min(rows, key=lambda r: abs(r[2]))
    density0, predicted0 = reference[3], reference[4]
    if density0 == 0.0:
        # Nothing bound on the reference (its binding switched off, or a run stopped at
        # snapshot 0): every other density would be infinitely enriched.
        raise CortexError(f"{run.trajectory_path}: no copies of '{reference[1]}' on the least curved membrane "
                          f"'{reference[0]}' in the {len(used)} snapshot(s) from t = {start:g} s: "
                          "densities relative to it are undefined")
    for r in rows:
        r.append(r[3] / density0)
        r[4] = r[4] / predicted0
    return sorted(rows, key=lambda r: r[2]), len(used), start


def run(args):
    rows, used, start = table(args.outdir, args.start)
    print(f"# averaged over {used} snapshots from t = {start:g} s; densities relative to the least curved membrane")
    print(f"{'membrane':>12} {'species':>12} {'H (1/nm)':>10} {'density (/um^2)':>16} {'relative':>9} {'closed form':>12}")
    for name, species, H, density, predicted, relative in rows:
        print(f"{name:>12} {species:>12} {H:10.5f} {density:16.1f} {relative:9.3f} {predicted:12.3f}")
    if args.out:
        plt = plotting.pyplot()
        fig, ax = plt.subplots(figsize=args.size)
        H = np.array([r[2] for r in rows])
        ax.plot(H, [r[5] for r in rows], "o", color="C0", label="simulated")
        ax.plot(H, [r[4] for r in rows], "s", mfc="none", color="C3", label="dilute closed form")
        for r in rows:
            ax.annotate(r[0], (r[2], r[5]), textcoords="offset points", xytext=(4, 4), fontsize=8)
        ax.set_xlabel("mean curvature H (1/nm)")
        ax.set_ylabel("density / least curved membrane's")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        if args.title:
            ax.set_title(args.title)
        fig.tight_layout()
        plotting.save(fig, args.out, args.dpi)
        common.wrote(args.out)
    return 0
