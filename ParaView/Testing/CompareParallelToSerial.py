"""Runs TestParallel.py with pvbatch serially, with `mpiexec -np 2` and `-np 3 pvbatch`, and from
pvpython connected to a two-rank pvserver, then checks that, in every rotation mode, all give
the same edited surface up to point
order (parallel outputs repeat piece-boundary points): every point of each parallel output lies
within 1e-9 of a serial point, and every serial point within 1e-9 of a parallel one. In the
region of interest the refreshed point normals agree within 1e-6 too (elsewhere they are the
input's, and the pieces' input normals differ from the whole surface's along piece borders).

    python3 CompareParallelToSerial.py PLUGIN WORK_DIR MESH
"""
import bisect
import os
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
plugin, work, mesh = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
script = os.path.join(here, "TestParallel.py")
runs = {
    "serial": ["pvbatch", "--force-offscreen-rendering", script, plugin],
    "mpi": ["mpiexec", "-np", "2", "--oversubscribe", "pvbatch", "--force-offscreen-rendering",
            script, plugin],
    "mpi3": ["mpiexec", "-np", "3", "--oversubscribe", "pvbatch", "--force-offscreen-rendering",
             script, plugin],
}
modes = ("none", "explicit", "implicit", "implicit-linear", "arap")  # TestParallel.py's file suffixes
port = 11111 + os.getpid() % 1000
runs["pvserver"] = ["pvpython", script, plugin]
server = subprocess.Popen(
    ["mpiexec", "-np", "2", "--oversubscribe", "pvserver", "--force-offscreen-rendering",
     f"--server-port={port}"], env=environment, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
    text=True)
for line in server.stdout:  # wait until it listens
    if "Accepting connection" in line:
        break
points = {}
for name, command in runs.items():
    path = os.path.join(work, f"points-{name}.txt")
    extra = [str(port)] if name == "pvserver" else []
    result = subprocess.run(command + [path, mesh] + extra, env=environment, capture_output=True,
                            text=True, timeout=300)
    print(name, result.stdout.strip().splitlines()[-4:] if result.stdout else "", flush=True)
    if result.returncode != 0:
        print(result.stdout, result.stderr)
        sys.exit(f"FAILED: the {name} run exited with {result.returncode}")
    for mode in modes:
        with open(os.path.join(work, f"points-{name}-{mode}.txt")) as lines:
            points[name, mode] = sorted(tuple(map(float, line.split())) for line in lines)


def all_near(a, b, tolerance=1e-9):
    """The first point of `a` with no point of `b` within `tolerance` (and, in the region of
    interest, no matching normal), or None."""
    xs = [p[0] for p in b]
    for p in a:
        lo = bisect.bisect_left(xs, p[0] - tolerance)
        hi = bisect.bisect_right(xs, p[0] + tolerance)
        if not any(max(abs(p[k] - q[k]) for k in range(3)) <= tolerance and
                   (p[6] == 0 or max(abs(p[k] - q[k]) for k in range(3, 6)) <= 1e-6)
                   for q in b[lo:hi]):
            return p
    return None


server.wait(timeout=60)  # it exits when the client disconnects
for mode in modes:
    serial = points["serial", mode]
    for name in ("mpi", "mpi3", "pvserver"):
        parallel = points[name, mode]
        missing = all_near(parallel, serial) or all_near(serial, parallel)
        print(f"{mode}: serial {len(serial)} points, {name} {len(parallel)} points")
        if missing:
            sys.exit(f"FAILED: {mode}, {name}: point {missing} has no match in the other run")
print("pvbatch with 2 and 3 ranks and pvserver with 2 ranks match serial in every rotation "
      "mode, normals included")
