"""One snapshot of a run: its membranes, species copies and filaments as numpy arrays.

Each part is read from the snapshot file the first time it is asked for
(layout: docs/output.md and docs/filaments.md)."""

from functools import cached_property

import numpy as np

# Every filament dataset of a snapshot with its dtype and its shape when empty, so files
# written before a dataset existed read as empty arrays rather than failing.
FILAMENT_DATASETS = {
    "beads": (np.float64, (0, 3)),
    "offsets": (np.int64, (1,)),
    "ids": (np.int64, (0,)),
    "types": (np.int32, (0,)),
    "lengths": (np.float64, (0,)),
    "monomers": (np.int64, (0,)),
    "cylinders": (np.int32, (0, 2)),
    "cylinder_filament": (np.int32, (0,)),
    "linkers": (np.float64, (0, 2, 3)),
    "linker_types": (np.int32, (0,)),
    "linker_tensions": (np.float64, (0,)),
    "motors": (np.float64, (0, 2, 3)),
    "motor_types": (np.int32, (0,)),
    "motor_tensions": (np.float64, (0,)),
    "branch_points": (np.float64, (0, 3)),
}


class Membrane:
    """A triangle mesh: vertices (n,3) nm, triangles (m,3) vertex indices,
    mean_curvature (n) 1/nm or None when the file has none, contact_force (n,3) pN (the
    filaments' push on each vertex) or None in runs without membrane–filament contact,
    species: copies (n) per vertex by name of each membrane species (empty without)."""

    def __init__(self, name, vertices, triangles, mean_curvature, contact_force=None, species=None):
        self.name = name
        self.vertices = vertices
        self.triangles = triangles
        self.mean_curvature = mean_curvature
        self.contact_force = contact_force
        self.species = species or {}

    def cell_areas(self):
        """Dual-cell area |C_j| (nm^2) of every vertex: a third of the triangles around it,
        the area a vertex's copies stand for (density = copies / area)."""
        v, t = self.vertices, self.triangles
        area = 0.5 * np.linalg.norm(np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]]), axis=1)
        out = np.zeros(len(v))
        for k in range(3):
            np.add.at(out, t[:, k], area / 3.0)
        return out

    def __repr__(self):
        return f"<Membrane {self.name!r}: {len(self.vertices)} vertices, {len(self.triangles)} triangles>"


class Filaments:
    """The filament network: one attribute per dataset of FILAMENT_DATASETS (beads,
    offsets, ids, types, lengths, monomers, cylinders, cylinder_filament, linkers,
    linker_types, linker_tensions, motors, motor_types, motor_tensions, branch_points),
    and contact_force (k,3) pN per bead, or None in runs without membrane–filament contact."""

    def __init__(self, arrays):
        self.__dict__.update(arrays)

    def __len__(self):
        return len(self.offsets) - 1

    @property
    def polylines(self):
        """Beads of each filament, minus end first: a list of (k_i,3) arrays."""
        o = self.offsets
        return [self.beads[o[i]:o[i + 1]] for i in range(len(self))]

    @property
    def segments(self):
        """Cylinders as (m,2,3) end points."""
        return self.beads[self.cylinders]

    def __repr__(self):
        return (f"<Filaments: {len(self)} filaments, {len(self.beads)} beads, {len(self.linkers)} linkers, "
                f"{len(self.motors)} motors, {len(self.branch_points)} branch points>")


class Snapshot:
    """Snapshot `index` (group /snapshots/`name`) of a run."""

    def __init__(self, run, index, name):
        self.run = run
        self.index = index
        self.name = name

    def __repr__(self):
        return f"<Snapshot {self.name} of {self.run.path!r} at t = {self.time:g} s>"

    def _group(self):
        return self.run._group(self.name)

    @cached_property
    def time(self):
        """Time in s."""
        return float(self._group().attrs.get("time", np.nan))

    @cached_property
    def step(self):
        """Windows completed."""
        return int(self._group().attrs.get("step", -1))

    @cached_property
    def membranes(self):
        """Membranes by name in the config's order (Run.membrane_order; an empty dict in
        runs without them)."""
        g = self._group()
        if "membranes" not in g:
            return {}
        rank = {name: i for i, name in enumerate(self.run.membrane_order)}
        out = {}
        for name in sorted(g["membranes"], key=lambda n: (rank.get(n, len(rank)), n)):
            m = g["membranes"][name]
            h = np.asarray(m["mean_curvature"][()], dtype=float) if "mean_curvature" in m else None
            f = np.asarray(m["contact_force"][()], dtype=float) if "contact_force" in m else None
            species = ({k: np.asarray(d[()], dtype=np.int64) for k, d in m["species"].items()}
                       if "species" in m else {})
            out[name] = Membrane(name, np.asarray(m["vertices"][()], dtype=float),
                                 np.asarray(m["triangles"][()], dtype=np.int64), h, f, species)
        return out

    @cached_property
    def species(self):
        """Copies per compartment (nx,ny,nz) by species name (empty without [[species]])."""
        g = self._group()
        if "compartments/species" not in g:
            return {}
        return {name: d[()] for name, d in sorted(g["compartments/species"].items())}

    @cached_property
    def filaments(self):
        """The filament network, or None in runs without filaments."""
        g = self._group()
        if "filaments" not in g:
            return None
        fg = g["filaments"]
        arrays = {key: np.asarray(fg[key][()], dtype=dtype) if key in fg else np.zeros(shape, dtype)
                  for key, (dtype, shape) in FILAMENT_DATASETS.items()}
        # Per bead (k,3) pN, only in runs where membranes and filaments interact.
        arrays["contact_force"] = np.asarray(fg["contact_force"][()], dtype=float) if "contact_force" in fg else None
        return Filaments(arrays)
