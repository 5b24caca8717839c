#!/usr/bin/python3
"""Old name of `python3 -m cortex mesh-resolution` (docs/python.md)."""
import _cortex

_cortex.run("mesh-resolution")
