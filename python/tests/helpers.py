"""Running `python3 -m cortex` commands from the tests."""

import contextlib
import io
import os
import subprocess
import sys

from cortex import cli

PYTHON_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPOSITORY = os.path.dirname(PYTHON_DIR)


def command(*argv):
    """Run a command in this process: (exit code, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = cli.main([str(a) for a in argv])
        except SystemExit as e:          # argparse's own errors
            code = e.code
    return code, out.getvalue(), err.getvalue()


def python(*argv, env=None):
    """Run this Python interpreter (`-m cortex ...`, a script) with the package importable."""
    environment = dict(os.environ, PYTHONPATH=PYTHON_DIR, **(env or {}))
    return subprocess.run([sys.executable] + [str(a) for a in argv], capture_output=True, text=True,
                          env=environment)


def assert_png(test, path):
    test.assertTrue(os.path.isfile(path), f"{path} not written")
    with open(path, "rb") as f:
        test.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", path)
    test.assertGreater(os.path.getsize(path), 1000, path)
