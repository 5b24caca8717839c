"""What the old tool scripts share: they run a `python3 -m cortex` command from the
repository's python/ folder, so command lines written for them keep working."""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "python"))

from cortex.cli import main  # noqa: E402


def run(command, renamed=None):
    """Exit with `python3 -m cortex COMMAND` on this script's arguments, renaming the
    flags whose names changed ({"--old": "--new"}, also in the --old=value form)."""
    renamed = renamed or {}
    argv = []
    for arg in sys.argv[1:]:
        flag, eq, value = arg.partition("=")
        argv.append(renamed.get(flag, flag) + eq + value if flag in renamed else arg)
    sys.exit(main([command] + argv))
