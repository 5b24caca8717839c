"""The commands of `python3 -m cortex`, one module each: HELP, add_arguments(parser),
run(args) -> exit code."""

from . import (barrier, filaments, info, lining, llps, membrane, mesh_resolution, movie, plot, protrusion, rg, sorting,
               tubes)

# Command name -> module, in the order `--help` lists them.
COMMANDS = {
    "info": info,
    "plot": plot,
    "membrane": membrane,
    "filaments": filaments,
    "movie": movie,
    "rg": rg,
    "protrusion": protrusion,
    "tubes": tubes,
    "lining": lining,
    "barrier": barrier,
    "sorting": sorting,
    "llps": llps,
    "mesh-resolution": mesh_resolution,
}
