"""Read cortex runs and sweeps from Python, and the `python3 -m cortex` commands.

    import cortex
    with cortex.open("OUT") as run:
        v = run.observables["membranes.vesicle.reduced_volume"]
        x = run.snapshot(-1).membranes["vesicle"].vertices

Reference: docs/python.md. Needs numpy and h5py (matplotlib for the commands), which
Debian installs for /usr/bin/python3.
"""

try:
    import h5py  # noqa: F401  (checked here so the hint names the interpreter)
    import numpy  # noqa: F401
except ImportError as e:  # pragma: no cover - depends on the interpreter
    raise ImportError(f"cortex needs numpy and h5py ({e}); use /usr/bin/python3, "
                      "which has Debian's python3-numpy and python3-h5py") from e

from .errors import CortexError
from .run import Observables, Run, open
from .snapshot import Filaments, Membrane, Snapshot
from .sweep import SweepTable, open_sweep

__all__ = ["CortexError", "Filaments", "Membrane", "Observables", "Run", "Snapshot",
           "SweepTable", "open", "open_sweep"]
