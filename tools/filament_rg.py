#!/usr/bin/python3
"""Old name of `python3 -m cortex rg` (docs/python.md)."""
import _cortex

_cortex.run("rg")
