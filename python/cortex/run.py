"""A run folder: its summary, configuration, observables table and snapshots.

Layout (docs/output.md): OUTDIR/trajectory.h5 indexes snapshots/NNNNNN.h5 through
external links and holds the /observables table and the root attributes;
OUTDIR/observables.csv is the same table as text; OUTDIR/summary.json the final values.
"""

import builtins
import csv
import difflib
import fnmatch
import json
import os
import tomllib
from functools import cached_property

import h5py
import numpy as np

from .errors import CortexError
from .snapshot import Snapshot

TRAJECTORY = "trajectory.h5"


def open(outdir):  # noqa: A001 - cortex.open mirrors the builtin on purpose
    """The run in OUTDIR (a cortex output folder, or its trajectory.h5)."""
    return Run(outdir)


def text(value):
    """An HDF5 string attribute as str (h5py gives str or bytes depending on how it was written)."""
    return value.decode() if isinstance(value, bytes) else value


class Observables:
    """The observables table: one row per snapshot, one column per number of summary.json,
    named by its path (`time`, `membranes.vesicle.reduced_volume`, ...)."""

    def __init__(self, columns, values, source):
        self.columns = list(columns)
        self.values = np.asarray(values, dtype=float).reshape(-1, len(self.columns))
        self.source = source            # the file it was read from, for messages

    def __len__(self):
        return self.values.shape[0]

    def __contains__(self, name):
        return name in self.columns

    def __getitem__(self, name):
        if name not in self.columns:
            close = difflib.get_close_matches(name, self.columns, n=3, cutoff=0.5)
            hint = f"; did you mean {', '.join(close)}?" if close else ""
            raise CortexError(f"{self.source}: no observable column '{name}'{hint}")
        return self.values[:, self.columns.index(name)]

    @property
    def time(self):
        return self["time"]

    def matching(self, pattern):
        """Columns matching a shell pattern such as `membranes.*.reduced_volume`."""
        found = fnmatch.filter(self.columns, pattern)
        if not found:
            self[pattern]               # raises, naming the column and near matches
        return found

    def __repr__(self):
        return f"<Observables {len(self)} rows x {len(self.columns)} columns from {self.source}>"


class Run:
    """A cortex output folder. Files are opened on first use and kept open until close()
    (or the end of a `with` block); anything used after close() reopens them."""

    def __init__(self, outdir):
        path = os.fspath(outdir)
        if os.path.basename(path) == TRAJECTORY and os.path.isfile(path):
            path = os.path.dirname(path) or "."
        if not os.path.isdir(path):
            raise CortexError(f"{outdir}: no such run folder")
        self.path = path
        self._h5 = None

    # ------------------------------------------------------------------ files

    @property
    def trajectory_path(self):
        return os.path.join(self.path, TRAJECTORY)

    def _file(self):
        if self._h5 is None:
            path = self.trajectory_path
            if not os.path.isfile(path):
                raise CortexError(f"{path}: no such file (is {self.path} a cortex output folder?)")
            try:
                self._h5 = h5py.File(path, "r")
            except OSError as e:
                raise CortexError(f"{path}: not readable as HDF5 ({e})") from None
        return self._h5

    def close(self):
        if self._h5 is not None:
            self._h5.close()
            self._h5 = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __repr__(self):
        return f"<cortex.Run {self.path!r}: {len(self)} snapshots>"

    # --------------------------------------------------------------- metadata

    @cached_property
    def summary(self):
        """summary.json as a dict, or None when the run has not finished."""
        path = os.path.join(self.path, "summary.json")
        if not os.path.isfile(path):
            return None
        try:
            with builtins.open(path) as f:
                return json.load(f)
        except (OSError, ValueError) as e:
            raise CortexError(f"{path}: not readable as JSON ({e})") from None

    @cached_property
    def attrs(self):
        """Root attributes of trajectory.h5 (format, run_id, cortex_version, units, config)."""
        return {k: text(v) for k, v in self._file().attrs.items()}

    @property
    def config(self):
        """The run's effective configuration as TOML text (None in files older than it)."""
        return self.attrs.get("config")

    @cached_property
    def membrane_order(self):
        """Membrane names in the config's order, the order snapshots list them in (so "the
        first membrane" is the config's first, not the alphabetically first that HDF5
        groups give): from summary.json, else the stored config (a run stopped before its
        summary), else [] (then by name)."""
        try:
            if self.summary is not None:
                return [m.get("name") for m in self.summary.get("membranes", []) if isinstance(m, dict)]
            if self.config is not None:
                # An unnamed membrane is named as cortex names it (src/io/config.cpp).
                return [m.get("name", f"membrane{i}")
                        for i, m in enumerate(tomllib.loads(self.config).get("membrane", []))]
        except (CortexError, tomllib.TOMLDecodeError, AttributeError):
            pass                        # an unreadable summary or config: order by name
        return []

    # -------------------------------------------------------------- snapshots

    @cached_property
    def _names(self):
        f = self._file()
        return sorted(f["snapshots"].keys()) if "snapshots" in f else []

    def __len__(self):
        return len(self._names)

    def snapshot(self, i):
        """Snapshot i in time order; negative i counts from the end (-1 is the last)."""
        names = self._names
        if not isinstance(i, (int, np.integer)):
            raise CortexError(f"snapshot index {i!r}: expected an integer")
        if not -len(names) <= i < len(names):
            raise CortexError(f"{self.trajectory_path}: no snapshot {i} (the run has {len(names)})")
        i = int(i) % len(names)
        return Snapshot(self, i, names[i])

    def snapshots(self):
        """Every snapshot in time order."""
        return [self.snapshot(i) for i in range(len(self))]

    @cached_property
    def times(self):
        """Time (s) of every snapshot."""
        return np.array([s.time for s in self.snapshots()], dtype=float)

    def _group(self, name):
        """The HDF5 group of one snapshot (following its external link)."""
        try:
            return self._file()["snapshots"][name]
        except (KeyError, OSError) as e:
            raise CortexError(f"{self.trajectory_path}: snapshot {name} unreadable "
                              f"(snapshots/{name}.h5 missing or damaged: {e})") from None

    # ------------------------------------------------------------ observables

    @cached_property
    def observables(self):
        """The observables table, from trajectory.h5 or else observables.csv."""
        f = self._file()
        if "observables" in f:
            d = f["observables"]
            columns = text(d.attrs.get("columns", ""))
            if columns:
                return Observables(columns.split(","), d[()], f"{self.trajectory_path}:/observables")
        path = os.path.join(self.path, "observables.csv")
        if not os.path.isfile(path):
            raise CortexError(f"{self.path}: no observables (neither /observables in "
                              f"{TRAJECTORY} nor observables.csv)")
        with builtins.open(path, newline="") as fh:
            rows = list(csv.reader(fh))
        if not rows:
            raise CortexError(f"{path}: empty (no header line)")
        try:
            values = [[float(v) for v in row] for row in rows[1:]]
        except ValueError as e:
            raise CortexError(f"{path}: not a table of numbers ({e})") from None
        return Observables(rows[0], values, path)
