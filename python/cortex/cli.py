"""`python3 -m cortex COMMAND ...`: parse the command line, run the command, and turn
bad input (CortexError) into one line on stderr and exit code 2."""

import argparse
import sys

from .commands import COMMANDS
from .errors import CortexError


class Parser(argparse.ArgumentParser):
    """argparse with its errors (a missing argument, a flag value its type refuses) on one
    line, as the commands' own: argparse's usage lines before it would make two."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (--help lists the flags)\n")


def parser():
    p = Parser(
        prog="python3 -m cortex",
        description="Look at cortex runs: pictures, plots, movies, numbers (docs/python.md).",
        epilog="Every command takes the run folder(s) first and -o/--out FILE; "
               "`python3 -m cortex COMMAND --help` lists its flags. Exit code 2 on bad input.")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, module in COMMANDS.items():
        c = sub.add_parser(name, help=module.HELP, description=module.__doc__,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        module.add_arguments(c)
        c.set_defaults(run=module.run)
    return p


def main(argv=None):
    args = parser().parse_args(argv)
    try:
        return args.run(args)
    except CortexError as e:
        print(f"cortex {args.command}: error: {e}", file=sys.stderr)
        return 2
