"""cortex.open: what a Run reads equals what h5py reads directly and summary.json says."""

import json
import math
import os
import shutil
import tempfile
import unittest

import h5py
import numpy as np

import cortex
from tests import runs


def flatten(summary):
    """summary.json as {observables column: value}: membranes keyed by name, booleans 1/0,
    null NaN, seed and threads left out (docs/output.md)."""
    out = {}

    def walk(prefix, value):
        if isinstance(value, dict):
            for k, v in value.items():
                walk(f"{prefix}{k}.", v)
        elif isinstance(value, list):                  # only named objects (membranes) are columns
            for item in value:
                if isinstance(item, dict) and isinstance(item.get("name"), str):
                    walk(f"{prefix}{item['name']}.", item)
        elif value is None:
            out[prefix[:-1]] = math.nan
        elif isinstance(value, (bool, int, float)):
            out[prefix[:-1]] = float(value)

    walk("", {k: v for k, v in summary.items() if k not in ("seed", "threads")})
    return out


class RunTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.paths = {name: runs.path(name) for name in ("vesicle", "filaments", "species", "bundle")}

    def test_snapshots_match_h5py(self):
        with cortex.open(self.paths["vesicle"]) as run, h5py.File(run.trajectory_path, "r") as f:
            names = sorted(f["snapshots"])
            self.assertEqual(len(run), len(names))
            self.assertEqual(len(run), 5)
            np.testing.assert_array_equal(run.times, [f["snapshots"][n].attrs["time"] for n in names])
            for i in (0, 2, -1):
                s = run.snapshot(i)
                g = f["snapshots"][names[i]]["membranes/vesicle"]
                m = s.membranes["vesicle"]
                np.testing.assert_array_equal(m.vertices, g["vertices"][()])
                np.testing.assert_array_equal(m.triangles, g["triangles"][()])
                np.testing.assert_array_equal(m.mean_curvature, g["mean_curvature"][()])
                self.assertEqual(s.name, names[i])
            self.assertEqual(run.snapshot(-1).index, len(run) - 1)
            self.assertIsNone(run.snapshot(0).filaments)
            self.assertEqual(run.snapshot(0).species, {})

    def test_filaments_match_h5py(self):
        with cortex.open(self.paths["filaments"]) as run, h5py.File(run.trajectory_path, "r") as f:
            last = sorted(f["snapshots"])[-1]
            g = f["snapshots"][last]["filaments"]
            fil = run.snapshot(-1).filaments
            for key in cortex.snapshot.FILAMENT_DATASETS:
                np.testing.assert_array_equal(getattr(fil, key), g[key][()], err_msg=key)
            self.assertEqual(len(fil), 8)
            self.assertEqual(sum(len(p) for p in fil.polylines), len(fil.beads))
            self.assertEqual(fil.segments.shape, (len(fil.cylinders), 2, 3))
            self.assertGreater(len(fil.linkers) + len(fil.motors), 0, "the test run should bind some")

    def test_contact_forces_are_action_and_reaction(self):
        # Membrane–bead exclusion and filament excluded volume act between points of the
        # run and no wall is present, so the contact forces on all vertices and beads sum
        # to zero (translation invariance) while each side's sum is a push of pN.
        with cortex.open(self.paths["bundle"]) as run:
            s = run.snapshot(-1)
            membrane, filaments = s.membranes["patch"], s.filaments
            self.assertEqual(membrane.contact_force.shape, membrane.vertices.shape)
            self.assertEqual(filaments.contact_force.shape, filaments.beads.shape)
            on_membrane = membrane.contact_force.sum(axis=0)
            on_filaments = filaments.contact_force.sum(axis=0)
            self.assertGreater(on_membrane[2], 1.0)  # pushed up, towards +z
            np.testing.assert_allclose(on_membrane + on_filaments, 0.0, atol=1e-9 * np.abs(on_membrane).max())
        with cortex.open(self.paths["filaments"]) as run:
            self.assertIsNone(run.snapshot(-1).filaments.contact_force)  # no membrane: not written

    def test_species_match_h5py(self):
        with cortex.open(self.paths["species"]) as run, h5py.File(run.trajectory_path, "r") as f:
            last = sorted(f["snapshots"])[-1]
            s = run.snapshot(-1)
            self.assertEqual(sorted(s.species), ["A", "B"])
            for name, copies in s.species.items():
                np.testing.assert_array_equal(copies, f[f"snapshots/{last}/compartments/species/{name}"][()])
                self.assertEqual(copies.shape, (3, 3, 2))
            self.assertEqual(s.membranes, {})

    def test_observables_match_h5py_csv_and_summary(self):
        for name, outdir in self.paths.items():
            with self.subTest(run=name), cortex.open(outdir) as run:
                table = run.observables
                with h5py.File(run.trajectory_path, "r") as f:
                    np.testing.assert_array_equal(table.values, f["observables"][()])
                    self.assertEqual(table.columns, f["observables"].attrs["columns"].split(","))
                self.assertEqual(len(table), len(run))
                np.testing.assert_array_equal(table.time, run.times)
                final = flatten(run.summary)
                self.assertEqual(set(final), set(table.columns))
                for column, value in final.items():
                    if column != "wall_seconds":
                        np.testing.assert_equal(table[column][-1], value, err_msg=column)

    def test_observables_fall_back_to_csv(self):
        with tempfile.TemporaryDirectory() as tmp:
            copy = shutil.copytree(self.paths["vesicle"], os.path.join(tmp, "run"))
            with h5py.File(os.path.join(copy, "trajectory.h5"), "r+") as f:
                del f["observables"]
            with cortex.open(copy) as run, cortex.open(self.paths["vesicle"]) as original:
                self.assertTrue(run.observables.source.endswith("observables.csv"))
                self.assertEqual(run.observables.columns, original.observables.columns)
                np.testing.assert_array_equal(run.observables.values, original.observables.values)

    def test_metadata(self):
        run = cortex.open(os.path.join(self.paths["vesicle"], "trajectory.h5"))
        self.assertEqual(os.path.realpath(run.path), os.path.realpath(self.paths["vesicle"]))
        with open(os.path.join(run.path, "summary.json")) as f:
            self.assertEqual(run.summary, json.load(f))
        self.assertRegex(run.config, "name = ['\"]vesicle['\"]")
        self.assertTrue(run.attrs["format"].startswith("cortex trajectory"))
        self.assertIn("vesicle", repr(run.snapshot(-1).membranes["vesicle"]))
        run.close()
        self.assertIsNone(run._h5)
        self.assertEqual(run.snapshot(0).membranes["vesicle"].vertices.shape[1], 3, "reopens after close")
        run.close()

    def test_errors_name_what_is_missing(self):
        with tempfile.TemporaryDirectory() as tmp:
            with self.assertRaisesRegex(cortex.CortexError, "nowhere: no such run folder"):
                cortex.open(os.path.join(tmp, "nowhere"))
            with self.assertRaisesRegex(cortex.CortexError, "trajectory.h5: no such file"):
                len(cortex.open(tmp))
            with open(os.path.join(tmp, "trajectory.h5"), "w") as f:
                f.write("not hdf5")
            with self.assertRaisesRegex(cortex.CortexError, "trajectory.h5: not readable as HDF5"):
                len(cortex.open(tmp))
        with cortex.open(self.paths["vesicle"]) as run:
            with self.assertRaisesRegex(cortex.CortexError, "no snapshot 5 \\(the run has 5\\)"):
                run.snapshot(5)
            with self.assertRaisesRegex(cortex.CortexError, "no observable column 'membranes.vesicle.reduced_volum'"
                                        ".*did you mean membranes.vesicle.reduced_volume"):
                run.observables["membranes.vesicle.reduced_volum"]


if __name__ == "__main__":
    unittest.main()
