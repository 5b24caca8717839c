"""Renders one time step of a cortex run with ParaView, without a display:

    xvfb-run -a pvpython tools/paraview_picture.py OUTDIR [-o picture.png] [--time last|first|SECONDS]
                                                      [--species NAME] [--size 1200,900]

It opens OUTDIR/trajectory.xdmf with the Xdmf Reader, as the ParaView window would, and
shows each block the way docs/output.md describes it: membranes coloured by mean
curvature (blue convex, red concave, as in the thesis' fig. 2.3), filaments as grey
lines, linkers green, motors red, branch points blue, and the compartments coloured by a
species (the first, or --species) on the grid's faces, or only their outline when
membranes or filaments are shown. A starting point for your own pvpython scripts.
"""
import argparse
import os
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, ExtractBlock, GetActiveViewOrCreate, GetColorTransferFunction, LoadPalette,
                             Render, ResetCamera, SaveScreenshot, Show, XDMFReader)

BLOCK_COLOURS = {"filaments": (0.25, 0.25, 0.25), "linkers": (0.1, 0.6, 0.2), "motors": (0.85, 0.15, 0.1),
                 "branch_points": (0.1, 0.3, 0.9)}


def fail(message):
    print(f"paraview_picture.py: {message}", file=sys.stderr)
    sys.exit(2)


def block_names(reader, time):
    reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    return [data.GetMetaData(i).Get(data.NAME()) for i in range(data.GetNumberOfBlocks()) if data.GetBlock(i)]


def extract(reader, name):
    block = ExtractBlock(Input=reader)
    if hasattr(block, "Selectors"):  # ParaView >= 5.10
        block.Selectors = [f"/Root/{name}"]
    else:
        block.BlockIndices = [name]
    return block


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("-o", "--out", help="PNG to write (default OUTDIR/paraview.png)")
    parser.add_argument("--time", default="last", help="first, last or a time in s (default last)")
    parser.add_argument("--species", help="compartment species to colour by (default: the first)")
    parser.add_argument("--size", default="1200,900", help="width,height in pixels")
    args = parser.parse_args()

    xdmf = os.path.join(args.outdir, "trajectory.xdmf")
    if not os.path.isfile(xdmf):
        fail(f"{xdmf}: no such file (is {args.outdir} a cortex output folder?)")
    reader = XDMFReader(FileNames=[xdmf])
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    if args.time in ("first", "last"):
        time = times[0] if args.time == "first" else times[-1]
    else:
        try:
            time = min(times, key=lambda t: abs(t - float(args.time)))
        except ValueError:
            fail(f"--time: '{args.time}' is not first, last or a number")
    try:
        width, height = (int(v) for v in args.size.split(","))
    except ValueError:
        fail(f"--size: '{args.size}' is not width,height")

    LoadPalette("WhiteBackground")  # black text for the colour bars and axes
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = time

    names = block_names(reader, time)
    membranes = [n for n in names if n not in BLOCK_COLOURS and n != "compartments"]
    others = [n for n in names if n in BLOCK_COLOURS]
    largest = 0.0  # |H| over all membranes: one colour scale centred on flat
    for name in membranes:
        block = extract(reader, name)
        block.UpdatePipeline(time)
        low, high = block.PointData["mean_curvature"].GetRange()
        largest = max(largest, abs(low), abs(high))
        display = Show(block, view)
        ColorBy(display, ("POINTS", "mean_curvature"))
        display.SetScalarBarVisibility(view, True)
    if membranes:
        lut = GetColorTransferFunction("mean_curvature")
        lut.ApplyPreset("Cool to Warm", True)
        lut.InvertTransferFunction()  # blue convex (H > 0), red concave
        lut.RescaleTransferFunction(-largest, largest)
        lut.AutomaticRescaleRangeMode = "Never"
    for name in others:
        display = Show(extract(reader, name), view)
        display.ColorArrayName = ["POINTS", ""]  # solid colour
        display.AmbientColor = display.DiffuseColor = BLOCK_COLOURS[name]
        display.LineWidth = 2.0
        display.PointSize = 6.0
    if "compartments" in names:
        display = Show(extract(reader, "compartments"), view)
        if membranes or others:
            display.SetRepresentationType("Outline")
            display.ColorArrayName = ["POINTS", ""]  # solid colour
            display.AmbientColor = display.DiffuseColor = (0.5, 0.5, 0.5)
        else:
            reader.UpdatePipeline(time)
            arrays = [a.GetName() for a in reader.CellData]
            species = args.species or (arrays[0] if arrays else None)
            if species not in arrays:
                fail(f"--species: '{species}' is not a compartment species (have: {', '.join(arrays)})")
            display.SetRepresentationType("Surface With Edges")
            ColorBy(display, ("CELLS", species))
            display.SetScalarBarVisibility(view, True)
    elif args.species:
        fail("--species: this run has no compartment species")
    ResetCamera(view)
    view.CameraPosition = [p + d for p, d in zip(view.CameraFocalPoint, (1.2, -1.6, 1.0))]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    out = args.out or os.path.join(args.outdir, "paraview.png")
    SaveScreenshot(out, view, ImageResolution=[width, height])
    print(f"{out}: t = {time:g} s, blocks {', '.join(names)}")


if __name__ == "__main__":
    main()
