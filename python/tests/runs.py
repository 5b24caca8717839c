"""Tiny cortex runs for the Python tests, each a few seconds at most.

ctest runs this file first (fixture python_runs), which runs the cortex binary
($CORTEX_BINARY) on every config below into $CORTEX_TEST_RUNS/<name>; a test module run
on its own makes the runs it needs if they are missing.
"""

import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

# A vesicle shrinking from v = 1 to 0.85: 5 snapshots, a coarse mesh.
VESICLE = """
[simulation]
seed = 1
end_time = 0.2
chemistry_window = 0.05
snapshot_interval = 0.05

[[membrane]]
name = "vesicle"
shape = "sphere"
radius = 500.0
mesh_size = 100.0
bending_modulus = 100.0
reduced_volume = [[0.0, 1.0], [0.2, 0.85]]
"""

# An open patch with a fixed boundary bulging into a cap (examples/patch_bulge.toml, coarse).
PATCH = """
[simulation]
end_time = 0.0

[mechanics]
force_tolerance = 0.01

[[membrane]]
name = "patch"
shape = "plane"
size = [1000.0, 1000.0]
mesh_size = 100.0
boundary = "fixed"
bending_modulus = 100.0
spontaneous_curvature = 0.002
area_model = "none"
tension = 0.001
"""

# Eight filaments with fast-binding cross-linkers and motors: 6 snapshots.
FILAMENTS = """
[simulation]
seed = 3
end_time = 0.5
chemistry_window = 0.05
snapshot_interval = 0.1

[mechanics]
force_tolerance = 1.0
minimizer = "lbfgs"

[compartments]
size = 500.0
shape = [2, 2, 2]

[[species]]
name = "G"
diffusion = 2.0e7
concentration = 1.0

[[species]]
name = "AA"
diffusion = 2.0e6
concentration = 2.0

[[species]]
name = "MII"
diffusion = 2.0e5
concentration = 0.2

[[filament_type]]
name = "actin"
monomer_species = "G"
plus_on = 11.6
plus_off = 1.4
minus_on = 1.3
minus_off = 0.8

[[filaments]]
type = "actin"
count = 8
length = 400.0
placement = "random"
region = { min = [300.0, 300.0, 300.0], max = [700.0, 700.0, 700.0] }

[boundary]
shape = "box"

[[linker]]
name = "alpha-actinin"
species = "AA"
on_rate = 50.0
off_rate = 0.3

[[motor]]
name = "myosin"
species = "MII"
on_rate = 50.0
off_rate = 0.2
walk_rate = 20.0
"""

# Reaction-diffusion without membranes or filaments: species copies per compartment.
SPECIES = """
[simulation]
seed = 1
end_time = 0.03
chemistry_window = 0.01
snapshot_interval = 0.01

[compartments]
size = 500.0
shape = [3, 3, 2]

[[species]]
name = "A"
diffusion = 2.0e7
copies = 2000

[[species]]
name = "B"
diffusion = 2.0e6
copies = 0

[[reaction]]
equation = "2 A -> B"
rate = 0.01

[[reaction]]
equation = "B -> 2 A"
rate = 1.0
"""

# Three anchored filaments growing into a patch under tension (examples/bundle_protrusion.toml,
# small and short): 9 snapshots of a bulge that grows (until, later, the bundle tips
# over about its pinned minus ends).
BUNDLE = """
[simulation]
seed = 2
end_time = 0.2
chemistry_window = 0.01
snapshot_interval = 0.025

[compartments]
size = 250.0
shape = [2, 2, 2]

[[species]]
name = "G"
diffusion = 2.0e7
concentration = 10.0

[[membrane]]
name = "patch"
shape = "plane"
center = [250.0, 250.0, 300.0]
size = [500.0, 500.0]
mesh_size = 25.0
boundary = "fixed"
bending_modulus = 100.0
tension = 0.02
area_model = "none"

[[filament_type]]
name = "actin"
monomer_species = "G"

[[filaments]]
count = 3
length = 108.0
placement = "bundle"
center = [250.0, 250.0, 240.0]
direction = [0.0, 0.0, 1.0]
fixed_minus_end = true
"""

# A mixed bundle of 6 filaments pushing both poles of a small tense vesicle
# (examples/vesicle_tubes.toml, small and short): 5 snapshots of poles pushed out. The
# compartments are small enough for the 240 nm vesicle to be sliced right (cortex refuses
# a confining vesicle under one compartment across).
TUBES = """
[simulation]
seed = 3
end_time = 0.2
chemistry_window = 0.01
snapshot_interval = 0.05

[compartments]
size = 100.0
shape = [10, 5, 5]

[[species]]
name = "G"
diffusion = 2.0e7
copies = 150
inside = "vesicle"

[[membrane]]
name = "vesicle"
shape = "sphere"
center = [500.0, 250.0, 250.0]
radius = 120.0
mesh_size = 30.0
bending_modulus = 50.0
tension = 0.05
area_model = "none"
target_volume = 7.238e6
remesh = true

[[filament_type]]
name = "actin"
monomer_species = "G"

[[filaments]]
count = 6
length = 180.0
placement = "bundle"
polarity = "mixed"
center = [500.0, 250.0, 250.0]
direction = [1.0, 0.0, 0.0]
"""

# Membrane proteins starting left of a 1 k_BT Gaussian barrier on a 600 nm patch
# (examples/membrane_barrier.toml, small and short): 6 snapshots as copies cross it.
BARRIER = """
[simulation]
seed = 4
end_time = 0.05
chemistry_window = 0.01
snapshot_interval = 0.01

[[membrane]]
name = "patch"
shape = "plane"
center = [300.0, 300.0, 0.0]
size = [600.0, 600.0]
mesh_size = 50.0
boundary = "fixed"
bending_modulus = 100.0
area_model = "none"

[[membrane.species]]
name = "M"
diffusion = 1.0e6
copies = 2000
region = { min = [-1.0, -1.0, -1.0], max = [200.0, 601.0, 1.0] }

[membrane.species.potential]
type = "gaussian_stripe"
center = 300.0
width = 80.0
height = 1.0

[compartments]
size = 700.0
"""

# Curvature sorting (examples/curvature_sorting.toml, small and short): a curvature-
# sensing protein binding from one well-mixed box to vesicles of radii 100 and 250 nm.
SORTING = """
[simulation]
seed = 6
end_time = 0.6
chemistry_window = 0.05
snapshot_interval = 0.1

[[membrane]]
name = "small"
shape = "sphere"
center = [300.0, 700.0, 700.0]
radius = 100.0
mesh_size = 30.0
bending_modulus = 100.0

[[membrane.species]]
name = "B_small"

[membrane.species.curvature]
area = 20.0
bending_modulus = 200.0
spontaneous_curvature = 0.1

[[membrane]]
name = "large"
shape = "sphere"
center = [950.0, 700.0, 700.0]
radius = 250.0
mesh_size = 50.0
bending_modulus = 100.0

[[membrane.species]]
name = "B_large"

[membrane.species.curvature]
area = 20.0
bending_modulus = 200.0
spontaneous_curvature = 0.1

[compartments]
size = 1400.0

[[species]]
name = "C"
copies = 3000

[[reaction]]
equation = "C -> B_small"
rate = 30000.0
[[reaction]]
equation = "B_small -> C"
rate = 10.0
[[reaction]]
equation = "C -> B_large"
rate = 30000.0
[[reaction]]
equation = "B_large -> C"
rate = 10.0
"""

# Phase separation (examples/membrane_llps.toml, a quarter of the patch, short): a strong
# pair attraction (h = 0.4 k_BT) with the crowding cap; 5 snapshots.
LLPS = """
[simulation]
seed = 8
end_time = 0.05
chemistry_window = 0.01
snapshot_interval = 0.01

[[membrane]]
name = "patch"
shape = "plane"
center = [100.0, 100.0, 0.0]
size = [200.0, 200.0]
mesh_size = 12.0
boundary = "fixed"
bending_modulus = 100.0
area_model = "none"

[[membrane.species]]
name = "P"
diffusion = 1.0e6
copies = 375
footprint = 19.6
interaction = { height = 0.4, range = 18.0 }

[compartments]
size = 300.0
shape = [1, 1, 1]
"""

CONFIGS = {"vesicle": VESICLE, "patch": PATCH, "filaments": FILAMENTS, "species": SPECIES, "bundle": BUNDLE,
           "barrier": BARRIER, "sorting": SORTING, "llps": LLPS, "tubes": TUBES}


def root():
    return os.environ.get("CORTEX_TEST_RUNS") or os.path.join(tempfile.gettempdir(), "cortex_python_test_runs")


def binary():
    return os.environ.get("CORTEX_BINARY") or os.path.join(HERE, "..", "..", "build", "cortex")


def generate(name):
    """Run cortex on CONFIGS[name] into root()/name, replacing an earlier run."""
    os.makedirs(root(), exist_ok=True)
    config = os.path.join(root(), f"{name}.toml")
    with open(config, "w") as f:
        f.write(CONFIGS[name])
    outdir = os.path.join(root(), name)
    done = subprocess.run([binary(), "run", config, "-o", outdir, "--overwrite"],
                          capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    if done.returncode != 0:
        raise RuntimeError(f"cortex run {config} failed ({done.returncode}): {done.stderr.strip()}")
    return outdir


def path(name):
    """The run folder of CONFIGS[name], made if it has no summary.json yet."""
    outdir = os.path.join(root(), name)
    if not os.path.isfile(os.path.join(outdir, "summary.json")):
        generate(name)
    return outdir


if __name__ == "__main__":
    for name in CONFIGS:
        print(f"{generate(name)}")
    sys.exit(0)
