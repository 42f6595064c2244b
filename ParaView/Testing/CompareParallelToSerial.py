"""Runs TestParallel.py with pvbatch serially and with `mpiexec -np 2`, then checks that both
give the same edited surface up to point order (the parallel output repeats piece-boundary
points): every point of each output lies within 1e-9 of a point of the other.

    python3 CompareParallelToSerial.py PLUGIN WORK_DIR MESH
"""
import bisect
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
plugin, work, mesh = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
script = os.path.join(here, "TestParallel.py")
runs = {
    "serial": ["pvbatch", "--force-offscreen-rendering", script, plugin],
    "mpi": ["mpiexec", "-np", "2", "--oversubscribe", "pvbatch", "--force-offscreen-rendering",
            script, plugin],
}
points = {}
for name, command in runs.items():
    path = os.path.join(work, f"points-{name}.txt")
    result = subprocess.run(command + [path, mesh], env=environment, capture_output=True, text=True, timeout=300)
    print(name, result.stdout.strip().splitlines()[-1:] if result.stdout else "", flush=True)
    if result.returncode != 0:
        print(result.stdout, result.stderr)
        sys.exit(f"FAILED: the {name} run exited with {result.returncode}")
    with open(path) as lines:
        points[name] = sorted(tuple(map(float, line.split())) for line in lines)


def all_near(a, b, tolerance=1e-9):
    xs = [p[0] for p in b]
    for p in a:
        lo = bisect.bisect_left(xs, p[0] - tolerance)
        hi = bisect.bisect_right(xs, p[0] + tolerance)
        if not any(max(abs(p[k] - q[k]) for k in range(3)) <= tolerance for q in b[lo:hi]):
            return p
    return None


serial, mpi = points["serial"], points["mpi"]
missing = all_near(mpi, serial) or all_near(serial, mpi)
print(f"serial {len(serial)} points, 2 ranks {len(mpi)} points")
if missing:
    sys.exit(f"FAILED: point {missing} has no match in the other run")
print("parallel matches serial")
