"""`movie`: an MP4 with one frame per snapshot for a membrane run and a filament run;
a PNG montage with --montage or without ffmpeg."""

import os
import shutil
import subprocess
import tempfile
import time
import unittest

import cortex
from tests import runs
from tests.helpers import assert_png, command, python

FFMPEG = shutil.which("ffmpeg")
FFPROBE = shutil.which("ffprobe")


def probe(path):
    """(frames, width, height) of the first video stream."""
    done = subprocess.run([FFPROBE, "-v", "error", "-select_streams", "v:0", "-count_frames",
                           "-show_entries", "stream=nb_read_frames,width,height", "-of", "default=nw=1", path],
                          capture_output=True, text=True, check=True)
    fields = dict(line.split("=", 1) for line in done.stdout.split())
    return int(fields["nb_read_frames"]), int(fields["width"]), int(fields["height"])


class MovieTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.runs = {name: runs.path(name) for name in ("vesicle", "filaments")}
        cls.tmp = tempfile.TemporaryDirectory()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    @unittest.skipIf(FFMPEG is None, "ffmpeg is not installed")
    def test_mp4_has_a_frame_per_snapshot(self):
        for name, outdir in self.runs.items():
            with self.subTest(run=name):
                out = os.path.join(self.tmp.name, f"{name}.mp4")
                start = time.monotonic()
                code, stdout, stderr = command("movie", outdir, "-o", out, "--fps", "5", "--size", "3.3")
                self.assertEqual(code, 0, stderr)
                self.assertLess(time.monotonic() - start, 30)
                self.assertGreater(os.path.getsize(out), 0)
                if FFPROBE is None:
                    continue
                frames, width, height = probe(out)
                self.assertEqual(frames, len(cortex.open(outdir)))
                self.assertEqual((width % 2, height % 2), (0, 0), "libx264 needs even sizes")

    def test_montage_on_request(self):
        out = os.path.join(self.tmp.name, "vesicle_montage.mp4")
        code, stdout, stderr = command("movie", self.runs["vesicle"], "--montage", "-o", out)
        self.assertEqual(code, 0, stderr)
        self.assertIn("--montage: wrote a montage of 5 of 5 snapshots", stdout)
        assert_png(self, os.path.join(self.tmp.name, "vesicle_montage.png"))
        self.assertFalse(os.path.exists(out))
        # --columns 5 puts the 5 panels in one row: a picture about five times as wide
        # as it is tall (the square grid's is 3 × 2 panels).
        row = os.path.join(self.tmp.name, "row.png")
        code, _, stderr = command("movie", self.runs["vesicle"], "--montage", "--columns", "5", "-o", row)
        self.assertEqual(code, 0, stderr)
        with open(row, "rb") as fh:
            header = fh.read(24)
        width, height = int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")
        self.assertGreater(width / height, 4.0)
        code, _, stderr = command("movie", self.runs["vesicle"], "--montage", "--columns", "0", "-o", row)
        self.assertEqual(code, 2)
        self.assertIn("argument --columns: '0': expected a whole number >= 1", stderr)

    def test_cutaway_leaves_out_the_near_half(self):
        # A sphere seen from the default view: the near half is the triangles whose
        # centroids point towards the viewer, about half of them.
        import numpy as np
        from cortex import plotting
        run = cortex.open(self.runs["vesicle"])
        m = next(iter(run.snapshot(0).membranes.values()))
        hide = plotting.facing_half(m.vertices, m.triangles, 20.0, -60.0)
        self.assertAlmostEqual(hide.mean(), 0.5, delta=0.05)
        e, a = np.radians(20.0), np.radians(-60.0)
        viewer = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
        near = (m.vertices[m.triangles].mean(axis=1) - m.vertices.mean(axis=0)) @ viewer
        self.assertTrue(hide[np.argmax(near)])  # the triangle nearest the viewer goes
        self.assertFalse(hide[np.argmin(near)])  # the farthest stays
        out = os.path.join(self.tmp.name, "cutaway.png")
        code, stdout, stderr = command("movie", self.runs["vesicle"], "--montage", "--cutaway", "--snapshot", "0",
                                       "-o", out)
        self.assertEqual(code, 0, stderr)
        assert_png(self, out)

    def test_montage_without_ffmpeg(self):
        empty = os.path.join(self.tmp.name, "no_programs")
        os.makedirs(empty, exist_ok=True)
        out = os.path.join(self.tmp.name, "filaments_movie.mp4")
        done = python("-m", "cortex", "movie", self.runs["filaments"], "--snapshot", "0,-1", "-o", out,
                      env={"PATH": empty})
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("ffmpeg not found: wrote a montage of 2 of 2 snapshots", done.stdout)
        assert_png(self, os.path.join(self.tmp.name, "filaments_movie.png"))


if __name__ == "__main__":
    unittest.main()
