"""Opens a cortex run's trajectory.xdmf with ParaView's "Xdmf Reader" (pvpython) and
checks what a user relies on, at the first and the last time step:

- every object keeps one block name (the name in the run's HDF5 files, never a name
  suffixed by the reader) and the same block position;
- membranes have as many points and cells as their HDF5 datasets;
- compartments (when the run has species) form one cell per compartment, with one cell
  array per species whose values are the HDF5 counts and whose cell centres are the
  compartments' centres;
- filament parts (cylinders, linkers, motors, branch points) have their HDF5 sizes.

Usage: pvpython check_xdmf.py OUTDIR. Exit 0 when all hold, 1 with a message otherwise.
"""
import os
import sys

import h5py
import numpy as np
from paraview import servermanager
from paraview.simple import XDMFReader
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.vtkFiltersCore import vtkCellCenters

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def blocks(reader, time):
    reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    return [(data.GetMetaData(i).Get(data.NAME()), data.GetBlock(i)) for i in range(data.GetNumberOfBlocks())]


def check_compartments(block, snapshot, species, size, where):
    shape = snapshot[f"compartments/species/{species[0]}"].shape
    check(block.GetNumberOfCells() == int(np.prod(shape)), f"{where}: {block.GetNumberOfCells()} cells for grid {shape}")
    cells = dsa.WrapDataObject(block).CellData
    for name in species:
        values = cells[name]
        check(values is not None and not isinstance(values, dsa.VTKNoneArray), f"{where}: no cell array {name}")
        if values is None or isinstance(values, dsa.VTKNoneArray):
            continue
        check(np.array_equal(np.asarray(values), snapshot[f"compartments/species/{name}"][:].ravel()),
              f"{where}: {name} differs from the HDF5 counts")
    centres = vtkCellCenters()
    centres.SetInputData(block)
    centres.Update()
    got = dsa.WrapDataObject(centres.GetOutput()).Points
    i, j, k = np.meshgrid(*(np.arange(n) for n in shape), indexing="ij")
    want = (np.stack([i, j, k], axis=-1).reshape(-1, 3) + 0.5) * size
    check(np.allclose(got, want), f"{where}: compartment cells are not at the compartments' centres")


def main(outdir):
    reader = XDMFReader(FileNames=[os.path.join(outdir, "trajectory.xdmf")])
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    index = h5py.File(os.path.join(outdir, "trajectory.h5"), "r")
    snapshots = sorted(index["snapshots"])
    check(len(times) == len(snapshots), f"{len(times)} time steps for {len(snapshots)} snapshots")
    first, last = blocks(reader, times[0]), blocks(reader, times[-1])
    check([n for n, _ in first] == [n for n, _ in last], f"block names change: {[n for n, _ in first]} -> {[n for n, _ in last]}")
    species = index.attrs["species"].split(",") if "species" in index.attrs else []
    membranes = set()
    for name in snapshots:
        membranes.update(index[f"snapshots/{name}"].get("membranes", {}).keys())
    filament_parts = {"filaments": "cylinders", "linkers": "linkers", "motors": "motors", "branch_points": "branch_points"}
    expected = sorted(membranes) + [p for p in filament_parts if any(
        f"snapshots/{s}/filaments/{filament_parts[p]}" in index and index[f"snapshots/{s}/filaments/{filament_parts[p]}"].shape[0] > 0
        for s in snapshots)] + (["compartments"] if species else [])
    check(sorted(n for n, _ in first) == sorted(expected), f"blocks {[n for n, _ in first]}, expected {expected}")
    for step, (time, found) in ((snapshots[0], (times[0], first)), (snapshots[-1], (times[-1], last))):
        snapshot = index[f"snapshots/{step}"]
        for name, block in found:
            where = f"t = {time}: block {name}"
            check(name is not None and "[" not in name, f"{where}: not a stable name")
            if block is None:
                continue
            if name in membranes:
                m = snapshot[f"membranes/{name}"]
                check(block.GetNumberOfPoints() == m["vertices"].shape[0], f"{where}: point count")
                check(block.GetNumberOfCells() == m["triangles"].shape[0], f"{where}: cell count")
            elif name == "compartments":
                check_compartments(block, snapshot, species, float(index.attrs["compartment_size"]), where)
            elif name in filament_parts:
                rows = snapshot[f"filaments/{filament_parts[name]}"].shape[0]
                check(block.GetNumberOfCells() == rows, f"{where}: {block.GetNumberOfCells()} cells for {rows} rows")
    if species:
        check(any(n == "compartments" and b is not None for n, b in first + last), "no compartment block with data")
    if failures:
        print(f"{outdir}:", *failures, sep="\n  ")
        return 1
    print(f"{outdir}: {len(times)} time steps, blocks {[n for n, _ in first]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
