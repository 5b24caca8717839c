"""The one exception the package raises for bad input."""


class CortexError(Exception):
    """A run folder, file, snapshot, membrane or column that is missing or unreadable.

    The message names the path and what is missing; the commands print it on one line
    and exit with code 2, as `cortex` itself does for bad input."""
