#!/usr/bin/python3
"""Old name of `python3 -m cortex membrane` (docs/python.md); --montage LIST is --snapshot LIST there."""
import _cortex

_cortex.run("membrane", {"--montage": "--snapshot"})
