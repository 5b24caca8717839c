"""The table a parameter sweep writes: SWEEPOUT/sweep.csv.

A header row, then one row per member: `member,status,seed`, the swept key paths
(e.g. `membrane.0.kappa`), `outdir` (relative to the sweep folder), `message`, then the
member's summary values in columns named like the observables columns. RFC 4180
quoting; numbers to 17 digits; empty or `nan` where a member has no value. Columns
this reader does not know are kept as they are.
"""

import builtins
import csv
import os

import numpy as np

from .errors import CortexError
from .run import Run

SWEEP_CSV = "sweep.csv"


def open_sweep(path):
    """The sweep in a folder (or its sweep.csv)."""
    return SweepTable(path)


def number(cell):
    """A cell as float: empty reads NaN; anything that is not a number raises ValueError."""
    return float(cell) if cell.strip() else float("nan")


class SweepTable:
    """sweep.csv as columns and rows; `status` "ok" marks members that finished."""

    def __init__(self, path):
        path = os.fspath(path)
        if not os.path.exists(path):
            raise CortexError(f"{path}: no such sweep folder or file")
        csv_path = os.path.join(path, SWEEP_CSV) if os.path.isdir(path) else path
        if not os.path.isfile(csv_path):
            raise CortexError(f"{csv_path}: no such file (is {path} a sweep folder?)")
        self.path = csv_path
        self.folder = os.path.dirname(csv_path) or "."
        with builtins.open(csv_path, newline="") as f:
            lines = list(csv.reader(f))
        if not lines:
            raise CortexError(f"{csv_path}: empty (no header row)")
        self.columns = lines[0]
        for n, row in enumerate(lines[1:], start=2):
            if len(row) != len(self.columns):
                raise CortexError(f"{csv_path}: row {n} (counting the header) has {len(row)} cells for {len(self.columns)} columns")
        self.rows = [dict(zip(self.columns, row)) for row in lines[1:]]

    def __len__(self):
        return len(self.rows)

    def __repr__(self):
        return f"<cortex.SweepTable {self.path!r}: {len(self)} members, {int(self.ok.sum())} ok>"

    def column(self, name):
        """One column: floats (NaN where empty) when every cell is a number, else strings."""
        if name not in self.columns:
            raise CortexError(f"{self.path}: no column '{name}' (columns: {', '.join(self.columns)})")
        cells = [row[name] for row in self.rows]
        try:
            return np.array([number(c) for c in cells], dtype=float)
        except ValueError:
            return np.array(cells, dtype=object)

    @property
    def ok(self):
        """Boolean mask of the members whose status is "ok"."""
        status = self.column("status") if self.rows else []
        return np.array([str(s).strip() == "ok" for s in status], dtype=bool)

    def run(self, i):
        """The run folder of member i (row i, from 0) as a cortex.Run."""
        if not -len(self) <= i < len(self):
            raise CortexError(f"{self.path}: no member {i} (the sweep has {len(self)})")
        outdir = self.rows[i].get("outdir", "")
        if not outdir:
            raise CortexError(f"{self.path}: member {i} has no outdir")
        return Run(os.path.join(self.folder, outdir))
