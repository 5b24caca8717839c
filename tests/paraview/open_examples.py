"""ctest driver: runs every example briefly (at most two snapshot intervals), opens its
trajectory.xdmf in ParaView with check_xdmf.py and renders it with
tools/paraview_picture.py (pvpython under xvfb-run).

Usage: python3 open_examples.py CORTEX PVPYTHON XVFB_RUN EXAMPLES_DIR WORKDIR
"""
import pathlib
import shutil
import subprocess
import sys
import tomllib


def short_end_time(config):
    sim = config.get("simulation", {})
    end = float(sim.get("end_time", 0.0))
    interval = sim.get("snapshot_interval")
    return end if interval is None else min(end, 2.0 * float(interval))


def main(cortex, pvpython, xvfb_run, examples, workdir):
    work = pathlib.Path(workdir)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    checker = pathlib.Path(__file__).with_name("check_xdmf.py")
    tools = pathlib.Path(__file__).resolve().parents[2] / "tools"
    failed = []
    for example in sorted(pathlib.Path(examples).glob("*.toml")):
        config = tomllib.loads(example.read_text())
        out = work / example.stem
        run = subprocess.run([cortex, "run", str(example), "-o", str(out), "--quiet",
                              "--set", f"simulation.end_time={short_end_time(config)}"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            failed.append(f"{example.name}: cortex run exited {run.returncode}: {run.stderr.strip()}")
            continue
        check = subprocess.run([xvfb_run, "-a", pvpython, str(checker), str(out)], capture_output=True, text=True)
        # pvpython's own chatter goes to stderr; the checker prints one summary line.
        lines = [line for line in check.stdout.splitlines() if line.strip()]
        print("\n".join(lines) if lines else f"{example.name}: no output; stderr: {check.stderr[-2000:]}")
        if check.returncode != 0:
            failed.append(f"{example.name}: ParaView check exited {check.returncode}")
        picture = out / "paraview.png"
        render = subprocess.run([xvfb_run, "-a", pvpython, str(tools / "paraview_picture.py"), str(out), "-o",
                                 str(picture), "--size", "400,300"], capture_output=True, text=True)
        if render.returncode != 0 or not picture.is_file() or picture.stat().st_size < 5000:
            failed.append(f"{example.name}: paraview_picture.py exited {render.returncode}: {render.stderr[-2000:]}")
    if failed:
        print("FAILED:", *failed, sep="\n  ")
        return 1
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:6]))
