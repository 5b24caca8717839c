"""cortex.open_sweep on a sweep.csv written here in the documented layout."""

import os
import tempfile
import unittest

import numpy as np

import cortex
from tests import runs


class SweepTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.folder = self.tmp.name
        self.vesicle = runs.path("vesicle")
        rel = os.path.relpath(self.vesicle, self.folder)
        # RFC 4180: a message with a comma, quotes and a line break; an extra unknown column
        self.csv = os.path.join(self.folder, "sweep.csv")
        with open(self.csv, "w", newline="") as f:
            f.write("member,status,seed,membrane.0.bending_modulus,outdir,message,"
                    "membranes.vesicle.reduced_volume,time,extra\r\n"
                    f"0,ok,1,100,{rel},,0.84999999999999998,0.20000000000000001,x\r\n"
                    '1,failed,2,200,member_1,"relaxation failed, ""folded""\nsee log",,nan,y\r\n'
                    "2,ok,3,3e2,member_2,,0.9,0.2,z\r\n")

    def tearDown(self):
        self.tmp.cleanup()

    def test_columns_rows_and_types(self):
        for path in (self.folder, self.csv):
            table = cortex.open_sweep(path)
            self.assertEqual(len(table), 3)
            self.assertEqual(table.columns[:3], ["member", "status", "seed"])
            np.testing.assert_array_equal(table.column("membrane.0.bending_modulus"), [100.0, 200.0, 300.0])
            v = table.column("membranes.vesicle.reduced_volume")
            self.assertEqual(v.dtype, float)
            self.assertEqual(v[0], 0.85)
            self.assertTrue(np.isnan(v[1]))
            self.assertTrue(np.isnan(table.column("time")[1]))
            self.assertEqual(list(table.column("extra")), ["x", "y", "z"])
            self.assertEqual(table.rows[1]["message"], 'relaxation failed, "folded"\nsee log')
            np.testing.assert_array_equal(table.ok, [True, False, True])

    def test_member_runs_open_relative_to_the_sweep(self):
        table = cortex.open_sweep(self.folder)
        with table.run(0) as run:
            self.assertEqual(os.path.realpath(run.path), os.path.realpath(self.vesicle))
            self.assertEqual(len(run), 5)
        with self.assertRaisesRegex(cortex.CortexError, "member_1: no such run folder"):
            table.run(1)
        with self.assertRaisesRegex(cortex.CortexError, "no member 3"):
            table.run(3)

    def test_errors(self):
        table = cortex.open_sweep(self.folder)
        with self.assertRaisesRegex(cortex.CortexError, "no column 'kappa'"):
            table.column("kappa")
        with self.assertRaisesRegex(cortex.CortexError, "nothing: no such sweep folder or file"):
            cortex.open_sweep(os.path.join(self.folder, "nothing"))
        with self.assertRaisesRegex(cortex.CortexError, "vesicle/sweep.csv: no such file"):
            cortex.open_sweep(self.vesicle)
        with open(self.csv, "a") as f:
            f.write("3,ok\r\n")
        with self.assertRaisesRegex(cortex.CortexError, "row 5 \\(counting the header\\) has 2 cells for 9 columns"):
            cortex.open_sweep(self.csv)


if __name__ == "__main__":
    unittest.main()
