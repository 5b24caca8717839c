"""Every command of `python3 -m cortex` on real runs; the old tools/ command lines; bad
input exits with code 2 and one line naming what is wrong."""

import math
import os
import shutil
import tempfile
import unittest

import h5py
import numpy as np

import cortex
from cortex import geometry
from tests import runs
from tests.helpers import REPOSITORY, assert_png, command, python


def surface_of_revolution(body, radius, reach, axis, centre, rings=400, around=64):
    """A closed, outward-oriented mesh: a sphere of radius `body` with tubes of `radius`
    out to `reach` from the centre along ±axis (no tubes when radius = body = reach)."""
    s = np.linspace(-reach, reach, rings)
    sphere = np.sqrt(np.maximum(body**2 - s**2, 0.0))
    rho = np.maximum(sphere, radius) if radius < body else sphere
    e1 = np.cross(axis, [0.0, 0.0, 1.0] if abs(axis[2]) < 0.9 else [1.0, 0.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(axis, e1)
    phi = np.linspace(0, 2 * np.pi, around, endpoint=False)
    points = [centre + si * axis + ri * (np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2)
              for si, ri in zip(s[1:-1], rho[1:-1])]
    vertices = np.vstack(points + [centre - reach * axis, centre + reach * axis])
    inner = rings - 2
    low, high = len(vertices) - 2, len(vertices) - 1
    triangles = []
    for i in range(inner - 1):
        for j in range(around):
            a, b = i * around + j, i * around + (j + 1) % around
            triangles += [[a, b, b + around], [a, b + around, a + around]]
    for j in range(around):
        triangles += [[low, (j + 1) % around, j],
                      [high, (inner - 1) * around + j, (inner - 1) * around + (j + 1) % around]]
    return cortex.snapshot.Membrane("v", vertices, np.array(triangles), np.zeros(len(vertices)))


class CommandsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # On a fresh machine the first use of matplotlib's fonts builds its cache and says so
        # on stderr: once here, not inside a test that counts the lines a command writes.
        import matplotlib.font_manager  # noqa: F401
        cls.runs = {name: runs.path(name) for name in ("vesicle", "patch", "filaments", "species", "bundle", "barrier", "sorting",
                                                  "llps", "tubes")}
        cls.tmp = tempfile.TemporaryDirectory()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def out(self, name):
        return os.path.join(self.tmp.name, name)

    def ok(self, *argv):
        code, stdout, stderr = command(*argv)
        self.assertEqual(code, 0, f"{argv}: {stderr}")
        return stdout

    def refused(self, argv, message):
        """The command exits 2 with one line on stderr holding `message`."""
        code, _, stderr = command(*argv)
        self.assertEqual(code, 2, f"{argv}: {stderr}")
        self.assertEqual(len(stderr.strip().splitlines()), 1, stderr)
        self.assertIn(message, stderr)

    def stopped(self, name, snapshots):
        """A copy of run `name` as a run stopped after its first `snapshots` snapshots
        leaves it: the later ones not in trajectory.h5, no summary.json."""
        path = self.out(f"{name}_stopped_{snapshots}")
        if not os.path.isdir(path):
            shutil.copytree(self.runs[name], path, ignore=shutil.ignore_patterns("summary.json"))
            with h5py.File(os.path.join(path, "trajectory.h5"), "a") as f:
                for key in sorted(f["snapshots"])[snapshots:]:
                    del f["snapshots"][key]
        return path

    def test_membrane(self):
        v = self.runs["vesicle"]
        self.ok("membrane", v, "-o", self.out("m1.png"))
        self.ok("membrane", v, "--snapshot", "0,2,last", "--align", "--edges", "-o", self.out("m2.png"))
        self.ok("membrane", v, "--snapshot", "first", "--views", "3", "--size", "2,2", "-o", self.out("m3.png"))
        self.ok("membrane", v, self.runs["patch"], "--labels", "vesicle,patch", "-o", self.out("m4.png"))
        for name in ("m1", "m2", "m3", "m4"):
            assert_png(self, self.out(f"{name}.png"))

    def test_filaments(self):
        f = self.runs["filaments"]
        self.ok("filaments", f, "-o", self.out("f1.png"))
        self.ok("filaments", f, "--snapshot", "all", "--views", "2", "--axis", "y", "--wall", "z=1000",
                "--ends", "--box", "0,0,0,1000,1000,1000", "--title", "test", "-o", self.out("f2.png"))
        assert_png(self, self.out("f1.png"))
        assert_png(self, self.out("f2.png"))

    def test_rg(self):
        f = self.runs["filaments"]
        stdout = self.ok("rg", f, f, "--labels", "a,b", "--bound", "--normalize", "--csv", self.out("rg.csv"),
                         "-o", self.out("rg.png"))
        self.assertIn("a: Rg", stdout)
        assert_png(self, self.out("rg.png"))
        with open(self.out("rg.csv")) as fh:
            lines = fh.read().splitlines()
        self.assertEqual(lines[0], "run,time_s,rg_nm,rg_rel,filaments,beads,linkers,motors,branch_points")
        self.assertEqual(len(lines), 1 + 2 * len(cortex.open(f)))
        self.assertIn("Rg", self.ok("rg", f, "--type", "0", "--per-length", "--quiet"))

    def test_barrier(self):
        b = self.runs["barrier"]
        stdout = self.ok("barrier", b, b, "--labels", "a,b", "--csv", self.out("b.csv"), "-o", self.out("b.png"))
        assert_png(self, self.out("b.png"))
        self.assertIn("a: fraction", stdout)
        with open(self.out("b.csv")) as fh:
            lines = fh.read().splitlines()
        self.assertEqual(lines[0], "run,time_s,fraction,right,total")
        self.assertEqual(len(lines), 1 + 2 * len(cortex.open(b)))
        # All 2000 copies start left of x = 200 nm: none past the barrier's centre at first,
        # a growing share later, and none lost on the way.
        rows = [[float(v) for v in line.split(",")[1:]] for line in lines[1:1 + len(cortex.open(b))]]
        self.assertEqual(rows[0][1], 0.0)
        self.assertGreater(rows[-1][1], 0.1)
        self.assertTrue(all(row[3] == 2000 for row in rows))
        code, _, stderr = command("barrier", b, "--species", "X")
        self.assertEqual(code, 2)
        self.assertIn("no species 'X'", stderr)

    def test_sorting(self):
        s = self.runs["sorting"]
        stdout = self.ok("sorting", s, "--from", "0.2", "-o", self.out("s.png"))
        assert_png(self, self.out("s.png"))
        rows = [line.split() for line in stdout.splitlines() if line.split()[:1] in (["small"], ["large"])]
        self.assertEqual([r[0] for r in rows], ["large", "small"])  # by curvature
        # Relative density and closed form: 1 for the reference; the small vesicle is
        # predicted ~1.9-fold enriched, and a short noisy run must at least show enrichment.
        self.assertEqual(float(rows[0][4]), 1.0)
        self.assertGreater(float(rows[1][5]), 1.5)
        self.assertGreater(float(rows[1][4]), 1.1)
        code, _, stderr = command("sorting", self.runs["vesicle"])
        self.assertEqual(code, 2)
        self.assertIn("no membrane species", stderr)

    def test_sorting_without_bound_copies_on_the_reference(self):
        # A run stopped at snapshot 0 has no copies bound anywhere: densities relative to
        # the least curved membrane's are undefined (not a ZeroDivisionError).
        self.refused(["sorting", self.stopped("sorting", 1)],
                     "no copies of 'B_large' on the least curved membrane 'large' in the 1 snapshot(s) from t = 0 s")

    def test_llps(self):
        p = self.runs["llps"]
        stdout = self.ok("llps", p, p, "--labels", "a,b", "--from", "0.02", "--csv", self.out("l.csv"),
                         "-o", self.out("l.png"))
        assert_png(self, self.out("l.png"))
        rows = {line.split()[0]: line.split() for line in stdout.splitlines() if line.split()[:1] in (["a"], ["b"])}
        # h read from the run's config; mean phi = 375 x 19.6 / 200^2; a strong attraction
        # gathers most copies into dense cells within 0.05 s.
        self.assertEqual(float(rows["a"][1]), 0.4)
        self.assertAlmostEqual(float(rows["a"][2]), 375 * 19.6 / 200.0**2, places=2)
        self.assertGreater(float(rows["a"][4]), 0.5)
        self.assertEqual(rows["a"][5], "yes")
        self.assertIn("onset of phase separation: h = 0.4 kT", stdout)
        with open(self.out("l.csv")) as fh:
            lines = fh.read().splitlines()
        self.assertEqual(lines[0], "run,height_kT,phi,probability")
        self.assertEqual(len(lines), 1 + 2 * 6)
        self.assertAlmostEqual(sum(float(line.split(",")[3]) for line in lines[1:7]), 1.0)
        code, _, stderr = command("llps", self.runs["barrier"])
        self.assertEqual(code, 2)
        self.assertIn("no footprint", stderr)

    def test_llps_says_how_each_run_was_pooled(self):
        # The whole run pools t = 0.01 .. 0.05 s (from a fifth of 0.05 s); one stopped
        # after 3 snapshots pools t = 0.01, 0.02 (from a fifth of 0.02 s): each row says so.
        stdout = self.ok("llps", self.runs["llps"], self.stopped("llps", 3), "--labels", "whole,stopped")
        rows = {line.split()[0]: line.split() for line in stdout.splitlines()
                if line.split()[:1] in (["whole"], ["stopped"])}
        self.assertEqual(rows["whole"][6:], ["5", "0.01"])
        self.assertEqual(rows["stopped"][6:], ["2", "0.004"])

    def test_protrusion(self):
        b = self.runs["bundle"]
        stdout = self.ok("protrusion", b, b, "--labels", "a,b", "--csv", self.out("p.csv"), "-o", self.out("p.png"))
        assert_png(self, self.out("p.png"))
        with open(self.out("p.csv")) as fh:
            lines = fh.read().splitlines()
        self.assertEqual(lines[0], "run,time_s,height_nm,tip_nm,filament_length_nm")
        self.assertEqual(len(lines), 1 + 2 * len(cortex.open(b)))
        # The tips start 6 nm under the flat patch and grow into it: a bulge that grows by
        # tens of nm, over tips that stay under it.
        rows = [[float(v) for v in line.split(",")[1:]] for line in lines[1:1 + len(cortex.open(b))]]
        self.assertLess(rows[0][1], 10.0)
        self.assertGreater(rows[-1][1], rows[0][1] + 20.0)
        for t, height, tip, length in rows:
            self.assertLess(tip, height)
        self.assertRegex(stdout, r"a: height [0-9.]+ -> [0-9.]+ nm, growth rate over the second half [0-9.]+ nm/s")

    def test_tubes(self):
        t = self.runs["tubes"]
        stdout = self.ok("tubes", t, t, "--labels", "a,b", "--csv", self.out("t.csv"), "-o", self.out("t.png"))
        assert_png(self, self.out("t.png"))
        with open(self.out("t.csv")) as fh:
            lines = fh.read().splitlines()
        self.assertEqual(lines[0], "run,time_s,body_radius_nm,plus_length_nm,plus_radius_nm,minus_length_nm,"
                                   "minus_radius_nm,plus_force_pN,minus_force_pN")
        self.assertEqual(len(lines), 1 + 2 * len(cortex.open(t)))
        # The bundle pushes both poles out of the round vesicle, symmetrically.
        first, last = ([float(v) for v in lines[k].split(",")[1:]] for k in (1, len(cortex.open(t))))
        self.assertLess(abs(first[2]), 3.0)
        self.assertGreater(last[2], 10.0)
        self.assertLess(abs(last[2] - last[4]), 0.2 * last[2])
        self.assertIn("(√(κ/2γ) = 22.4 nm)", stdout)
        self.assertIn("(2π√(2κγ) = 14.05 pN)", stdout)
        # The membrane pushes back on both poles: equal and opposite forces when the
        # bundle is still (its beads feel nothing else along the axis but its own springs).
        self.assertGreater(last[6], 0.5)
        self.assertLess(abs(last[6] - last[7]), 0.3 * last[6])

    def test_lining(self):
        # On a sphere of 200 nm: a filament 10 nm under the membrane along it counts as
        # near and parallel, one along a radius from the centre as far; the sphere is
        # smooth. Then the command on a run, with its table and plot.
        from types import SimpleNamespace

        from cortex.commands import lining
        membrane = surface_of_revolution(body=200.0, radius=200.0, reach=200.0, axis=np.array([0.0, 0.0, 1.0]),
                                         centre=np.zeros(3))
        along = np.array([[190.0, y, 0.0] for y in np.linspace(-20.0, 20.0, 5)])
        radial = np.array([[0.0, 0.0, z] for z in np.linspace(0.0, 100.0, 3)])
        near, cos = lining.lining(membrane, SimpleNamespace(polylines=[along, radial]), 50.0)
        self.assertAlmostEqual(near, 40.0 / 140.0, places=12)
        self.assertLess(cos, 0.1)
        excess, spread = lining.roughness(membrane)
        self.assertLess(abs(excess), 1e-3)
        self.assertLess(spread, 1e-3)
        # Ruffles: none on the sphere; on an ellipsoid of axes ±15% (its radius spread 13
        # nm) the degree-4 fit leaves 0.1 nm; 8 Gaussian bumps 10 nm high and 30 nm wide
        # (their area-weighted rms 1.54 nm, highest 10.5 nm where two overlap) are what
        # is left, less the little of them the fit takes up.
        self.assertLess(lining.ruffles(membrane)[0], 1e-6)
        ellipsoid = cortex.snapshot.Membrane("v", membrane.vertices * [1.15, 1.0, 0.9], membrane.triangles, None)
        self.assertLess(lining.ruffles(ellipsoid)[0], 0.2)
        u = membrane.vertices / np.linalg.norm(membrane.vertices, axis=1)[:, None]
        spots = np.random.default_rng(1).normal(size=(8, 3))
        spots /= np.linalg.norm(spots, axis=1)[:, None]
        bumps = sum(10.0 * np.exp(-(np.arccos(np.clip(u @ s, -1, 1)) / 0.15) ** 2) for s in spots)
        raised = membrane.vertices * (1 + bumps / 200.0)[:, None]
        bumpy = cortex.snapshot.Membrane("v", raised, membrane.triangles, None)
        rms, highest, count, diameter = lining.ruffles(bumpy, bump=5.0)
        self.assertGreater(rms, 0.8 * 1.54)
        self.assertLess(rms, 1.54)
        self.assertGreater(highest, 0.8 * 10.5)
        self.assertLess(highest, 10.5)
        # Over 5 nm: 7 patches (two of the bumps are 15° apart and merge), each about
        # 2 × 200 nm × 0.15 √(ln 2) = 50 nm across at half height, less the fit's share.
        self.assertEqual(count, 7)
        self.assertGreater(diameter, 35.0)
        self.assertLess(diameter, 55.0)
        self.assertEqual(lining.ruffles(membrane, bump=5.0)[2], 0)
        t = self.runs["tubes"]
        stdout = self.ok("lining", t, "--within", "60", "--csv", self.out("l.csv"), "-o", self.out("l.png"))
        assert_png(self, self.out("l.png"))
        with open(self.out("l.csv")) as fh:
            lines = fh.read().splitlines()
        self.assertEqual(lines[0], "run,time_s,near_fraction,near_mean_abs_cos,excess_area,radius_sd_over_mean,"
                                   "ruffle_rms_nm,ruffle_max_nm,bumps,bump_diameter_nm")
        self.assertEqual(len(lines), 1 + len(cortex.open(t)))
        self.assertIn("of the filament length within 60 nm of the membrane", stdout)

    def test_tube_with_pressure(self):
        # Without pressure the flat-membrane tube: √(κ/2γ), 2π√(2κγ). With one, the radius
        # is where the cost per length e(r) = πκ/r + 2πγr − πΔp r² is least (e rises on
        # both sides) and the force is e there; past Δp = (2γ)^{3/2}/√(27κ) no tube holds.
        from cortex.commands import tubes
        r, f = tubes.tube_with_pressure(50.0, 0.005, 0.0)
        self.assertAlmostEqual(r, math.sqrt(50.0 / 0.01), places=9)
        self.assertAlmostEqual(f, 2 * math.pi * math.sqrt(0.5), places=9)
        rng = np.random.default_rng(4)
        for _ in range(50):
            kappa, tension = rng.uniform(20.0, 200.0), rng.uniform(1e-3, 0.05)
            limit = (2 * tension) ** 1.5 / math.sqrt(27 * kappa)
            pressure = rng.uniform(-1.0, 0.95) * limit
            r, f = tubes.tube_with_pressure(kappa, tension, pressure)
            def cost(x):
                return math.pi * kappa / x + 2 * math.pi * tension * x - math.pi * pressure * x * x
            self.assertAlmostEqual(f, cost(r), delta=1e-9 * f)
            self.assertLess(cost(r), cost(r * 1.001))
            self.assertLess(cost(r), cost(r * 0.999))
            self.assertIsNone(tubes.tube_with_pressure(kappa, tension, 1.01 * limit))

    def test_tubes_measure_a_surface_of_revolution(self):
        # A sphere of radius 200 nm with tubes of radius 25 nm reaching 150 nm beyond it
        # at both poles, along a tilted axis: the command's measurement returns the body
        # radius, both lengths and both radii (to the mesh's resolution).
        from cortex.commands import tubes
        body, radius, reach = 200.0, 25.0, 350.0
        axis = np.array([1.0, 2.0, 2.0]) / 3.0
        membrane = surface_of_revolution(body, radius, reach, axis, centre=np.array([500.0, 400.0, 300.0]))
        volume, _ = geometry.volume_centroid(membrane.vertices, membrane.triangles)
        self.assertGreater(volume, 0)  # outward orientation, as cortex writes meshes
        measured = tubes.shape(membrane, -axis)
        self.assertAlmostEqual(measured[0], body, delta=1.0)
        for length, r in (measured[1:3], measured[3:5]):
            self.assertAlmostEqual(length, reach - body, delta=2.0)
            self.assertAlmostEqual(r, radius, delta=0.1)
        # A longer tube that has drifted 40 nm off the bundle's line is measured about its
        # own axis: still 25 nm, not the ~47 nm of its distance from that line.
        membrane = surface_of_revolution(body, radius, 800.0, axis, centre=np.zeros(3), rings=800)
        off = membrane.vertices @ axis > 250.0
        membrane.vertices[off] += 40.0 * np.cross(axis, [1.0, 0.0, 0.0]) / np.linalg.norm(np.cross(axis, [1.0, 0, 0]))
        measured = tubes.shape(membrane, axis)
        self.assertAlmostEqual(measured[1], 600.0, delta=2.0)
        self.assertAlmostEqual(measured[2], radius, delta=0.1)
        self.assertAlmostEqual(measured[4], radius, delta=0.1)
        code, _, stderr = command("tubes", self.runs["vesicle"])
        self.assertEqual(code, 2)
        self.assertIn("has no filaments", stderr)
        for name in ("tubes", "lining"):
            code, _, stderr = command(name, self.runs["bundle"])  # a patch
            self.assertEqual(code, 2)
            self.assertIn("membrane 'patch' is open: this measures a vesicle", stderr)

    def test_mesh_resolution(self):
        stdout = self.ok("mesh-resolution", self.runs["vesicle"], "--mesh-size", "100", "-o", self.out("res.png"))
        self.assertIn("mean edge", stdout)
        assert_png(self, self.out("res.png"))

    def test_plot(self):
        self.ok("plot", self.runs["vesicle"], "membranes.vesicle.reduced_volume", "membranes.*.energy.total",
                "-o", self.out("plot.png"))
        assert_png(self, self.out("plot.png"))
        self.ok("plot", self.runs["species"], "chemistry.species.*", "--x", "chemistry.events", "-o", self.out("p2.png"))
        assert_png(self, self.out("p2.png"))

    def test_info(self):
        stdout = self.ok("info", self.runs["vesicle"], "--snapshot", "0")
        self.assertIn("5 snapshots", stdout)
        self.assertIn("shape class: sphere", stdout)
        self.assertIn("membranes.vesicle.reduced_volume", stdout)
        self.assertIn("8 filaments", self.ok("info", self.runs["filaments"]))
        self.assertIn("species (copies, grid 3x3x2)", self.ok("info", self.runs["species"]))
        # Membrane species: all 2000 copies of the barrier run, in every snapshot.
        self.assertIn("species: M 2000 (mean", self.ok("info", self.runs["barrier"], "--snapshot", "last"))

    def test_open_patch_is_not_a_vesicle(self):
        stdout = self.ok("info", self.runs["patch"])
        self.assertIn("shape class: open patch", stdout)
        self.assertIn("no enclosed volume", stdout)
        self.assertNotIn("reduced volume", stdout)
        self.assertIn("shape class: open patch", self.ok("membrane", self.runs["patch"], "--info"))
        with cortex.open(self.runs["patch"]) as run:
            m = run.snapshot(-1).membranes["patch"]
        self.assertGreater(geometry.boundary_edge_count(m.triangles), 0)
        self.assertEqual(geometry.classify(m.vertices, m.triangles)[0], "open patch")
        # a closed vesicle with one triangle removed is open too
        with cortex.open(self.runs["vesicle"]) as run:
            v = run.snapshot(0).membranes["vesicle"]
        self.assertEqual(geometry.classify(v.vertices, v.triangles)[0], "sphere")
        self.assertEqual(geometry.classify(v.vertices, v.triangles[1:])[0], "open patch")

    def test_bad_input_exits_2_with_one_line(self):
        v, s = self.runs["vesicle"], self.runs["species"]
        cases = [
            (["info", os.path.join(v, "missing")], "missing: no such run folder"),
            (["membrane", v, "--snapshot", "9"], "no snapshot 9 (the run has 5"),
            (["membrane", v, "--snapshot", "middle"], "--snapshot 'middle'"),
            (["membrane", v, "--membrane", "cell"], "has no membrane 'cell' (it has vesicle)"),
            (["membrane", v, "--labels", "a,b"], "--labels has 2 entries for 1 panels"),
            (["membrane", v, "-o", os.path.join(v, "no", "such", "dir.png")], "dir.png: cannot write"),
            (["plot", v, "nonsense"], "no observable column 'nonsense'"),
            (["filaments", v], "holds no filaments"),
            (["filaments", self.runs["filaments"], "--wall", "q=3"], "--wall 'q=3'"),
            (["rg", v], "no snapshot with filaments"),
            (["mesh-resolution", s], "holds no membranes"),
            (["movie", s], "no membranes or filaments to draw"),
        ]
        for argv, message in cases:
            with self.subTest(argv=argv):
                code, _, stderr = command(*argv)
                self.assertEqual(code, 2)
                self.assertEqual(len(stderr.strip().splitlines()), 1, stderr)
                self.assertIn(message, stderr)
        code, _, stderr = command("membrane", v, "--size", "big")
        self.assertEqual(code, 2)
        self.assertIn("argument --size: 'big': expected W or W,H", stderr)

    def test_first_membrane_is_the_configs_first(self):
        # The sorting config lists 'small' before 'large' (HDF5 lists its groups by
        # name): the default membrane is 'small', read from summary.json, or from the
        # stored config in a run stopped before its summary.
        for run in (self.runs["sorting"], self.stopped("sorting", 2)):
            with self.subTest(run=run):
                self.assertEqual(list(cortex.open(run).snapshot(0).membranes), ["small", "large"])
                self.assertIn("membrane 'small'", self.ok("membrane", run, "--info").splitlines()[0])
                self.assertIn("membrane 'small', species 'B_small'", self.ok("barrier", run).splitlines()[0])

    def test_flag_values_are_checked(self):
        # Zero, negative or non-finite numbers and pictures in formats matplotlib does not
        # write: exit 2 naming the flag, before anything is read or drawn.
        v, b, s, p = self.runs["vesicle"], self.runs["barrier"], self.runs["sorting"], self.runs["llps"]
        png = self.out("refused.png")
        cases = [
            (["llps", p, "--bins", "0"], "argument --bins: '0': expected a whole number >= 1"),
            (["llps", p, "--bins", "-1"], "argument --bins: '-1'"),
            (["llps", p, "--from", "nan"], "argument --from: 'nan': expected a finite number"),
            (["sorting", s, "--from", "nan"], "argument --from: 'nan': expected a finite number"),
            (["plot", v, "time", "--dpi", "0", "-o", png], "argument --dpi: '0': expected a whole number >= 1"),
            (["membrane", v, "--dpi", "-5", "-o", png], "argument --dpi: '-5'"),
            (["movie", v, "--montage", "--dpi", "0", "-o", png], "argument --dpi: '0'"),
            (["barrier", b, "--dpi", "0", "-o", png], "argument --dpi: '0'"),
            (["plot", v, "time", "-o", self.out("x.txt")], "x.txt': expected a picture file ending in"),
            (["membrane", v, "-o", self.out("x.foo")], "argument -o/--out:"),
            (["sorting", s, "-o", self.out("x.txt")], "argument -o/--out:"),
            (["plot", v, "time", "-o", self.out("no_extension")], "argument -o/--out:"),
            (["barrier", b, "--split", "nan"], "argument --split: 'nan': expected a finite number"),
            (["mesh-resolution", v, "--mesh-size", "-5"], "argument --mesh-size: '-5': expected a number > 0"),
            (["mesh-resolution", v, "--mesh-size", "0"], "argument --mesh-size: '0'"),
            (["membrane", v, "--clim", "nan"], "argument --clim: 'nan'"),
            (["membrane", v, "--size", "nan", "-o", png], "argument --size: 'nan'"),
        ]
        for argv, message in cases:
            with self.subTest(argv=argv):
                self.refused(argv, message)
        self.assertFalse(os.path.exists(png))
        self.assertFalse(os.path.exists(self.out("no_extension.png")))

    def test_module_and_old_tool_command_lines(self):
        v, f = self.runs["vesicle"], self.runs["filaments"]
        done = python("-m", "cortex", "info", v)
        self.assertEqual(done.returncode, 0, done.stderr)
        tools = os.path.join(REPOSITORY, "tools")
        for argv, png in [
            (["render_membrane.py", v, "--montage", "0,last", "--out", self.out("t1.png")], "t1.png"),
            (["render_filaments.py", f, "--snapshots", "0,last", "-o", self.out("t2.png")], "t2.png"),
            (["filament_rg.py", f, "-o", self.out("t3.png")], "t3.png"),
            (["mesh_resolution.py", v, "--out", self.out("t4.png")], "t4.png"),
        ]:
            with self.subTest(tool=argv[0]):
                done = python(os.path.join(tools, argv[0]), *argv[1:])
                self.assertEqual(done.returncode, 0, done.stderr)
                assert_png(self, self.out(png))
        done = python(os.path.join(tools, "render_membrane.py"), v, "--snapshot", "12")
        self.assertEqual(done.returncode, 2)
        self.assertIn("no snapshot 12", done.stderr)


if __name__ == "__main__":
    unittest.main()
