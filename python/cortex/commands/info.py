"""What a run holds: version, snapshots and times, whether it finished, the membranes,
filaments and species of a snapshot (membranes with area, volume, reduced volume,
semi-axes and a shape class; "open patch" for a membrane with a boundary), and every
observables column with its first and last value (the names `plot` takes).

  info OUT
  info OUT --snapshot 0 --membrane vesicle
"""

from .. import report
from ..errors import CortexError
from . import common

HELP = "print what a run holds: snapshots, shapes, observables columns"


def add_arguments(p):
    common.add_outdirs(p, many=True)
    common.add_snapshot(p, "last")
    common.add_membrane(p)


def finished(run):
    s = run.summary
    if s is None:
        return "no summary.json (still running, stopped or failed)"
    return f"summary.json: t = {s.get('time', float('nan')):.6g} s, {s.get('wall_seconds', float('nan')):.3g} s wall"


def describe(run, args):
    times = run.times
    print(f"{run.path}: cortex {run.attrs.get('cortex_version', '?')}, {len(run)} snapshots, "
          f"t = {times[0]:.6g} .. {times[-1]:.6g} s; {finished(run)}")
    for i in common.snapshot_indices(run, args.snapshot):
        s = run.snapshot(i)
        for m in (common.membranes_of(s, args.membrane) if s.membranes or args.membrane else []):
            print("\n".join(report.membrane_lines(s, m)))
        if s.filaments is not None:
            print("\n".join(report.filament_lines(s, s.filaments)))
        if s.species:
            print("\n".join(report.species_lines(s, s.species)))
    try:
        table = run.observables
    except CortexError as e:
        print(f"observables: {e}")
        return
    print(f"observables ({len(table)} rows; first -> last):")
    width = max(map(len, table.columns))
    for name, column in zip(table.columns, table.values.T):
        values = f"{column[0]:.6g} -> {column[-1]:.6g}" if len(column) else "(no rows)"
        print(f"  {name:<{width}}  {values}")


def run(args):
    for outdir in args.outdir:
        with common.open_run(outdir) as r:
            describe(r, args)
    return 0
