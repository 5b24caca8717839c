"""ctest driver: runs every example briefly (at most two snapshot intervals), opens its
trajectory.xdmf in ParaView with check_xdmf.py and renders it with
tools/paraview_picture.py (pvpython on one virtual X server, started here and waited
for: an xvfb-run per call raced its own server start on a loaded machine, and a
picture then aborted).

Usage: python3 open_examples.py CORTEX PVPYTHON XVFB EXAMPLES_DIR WORKDIR
"""
import contextlib
import os
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


@contextlib.contextmanager
def virtual_display(xvfb):
    """An X server for the block; DISPLAY set. -displayfd reports the display number
    once the server accepts connections; -noreset keeps it from resetting whenever its
    last client leaves (each pvpython is one), when the next one to connect can be refused
    ("bad X server connection")."""
    read, write = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(write), "-noreset", "-screen", "0", "1280x1024x24",
                               "-nolisten", "tcp"],
                              pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write)
    with os.fdopen(read) as pipe:
        number = pipe.readline().strip()
    if not number:
        server.kill()
        raise RuntimeError(f"{xvfb} did not start")
    previous = os.environ.get("DISPLAY")
    os.environ["DISPLAY"] = f":{number}"
    try:
        yield
    finally:
        server.terminate()
        server.wait()
        if previous is None:
            os.environ.pop("DISPLAY", None)
        else:
            os.environ["DISPLAY"] = previous


def main(cortex, pvpython, xvfb, examples, workdir):
    with virtual_display(xvfb):
        return check_examples(cortex, pvpython, examples, workdir)


def check_examples(cortex, pvpython, examples, workdir):
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
        check = subprocess.run([pvpython, str(checker), str(out)], capture_output=True, text=True)
        # pvpython's own chatter goes to stderr; the checker prints one summary line.
        lines = [line for line in check.stdout.splitlines() if line.strip()]
        print("\n".join(lines) if lines else f"{example.name}: no output; stderr: {check.stderr[-2000:]}")
        if check.returncode != 0:
            failed.append(f"{example.name}: ParaView check exited {check.returncode}")
        picture = out / "paraview.png"
        # A window refused by the X server aborts pvpython (SIGABRT, "bad X server
        # connection"; seen under load before -noreset): a second attempt tells that apart
        # from a picture that fails.
        for attempt in range(2):
            render = subprocess.run([pvpython, str(tools / "paraview_picture.py"), str(out), "-o",
                                     str(picture), "--size", "400,300"], capture_output=True, text=True)
            drawn = render.returncode == 0 and picture.is_file() and picture.stat().st_size >= 5000
            if drawn:
                break
            print(f"{example.name}: picture attempt {attempt + 1} exited {render.returncode}: "
                  f"{render.stderr[:1500]}")
        if not drawn:
            failed.append(f"{example.name}: paraview_picture.py exited {render.returncode}: {render.stderr[:1500]}")
    if failed:
        print("FAILED:", *failed, sep="\n  ")
        return 1
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:6]))
