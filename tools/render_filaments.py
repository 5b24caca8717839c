#!/usr/bin/python3
"""Old name of `python3 -m cortex filaments` (docs/python.md); --snapshots is --snapshot there."""
import _cortex

_cortex.run("filaments", {"--snapshots": "--snapshot"})
