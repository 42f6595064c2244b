"""Bytes moved between MPI ranks by an edit, at setup and per move, with time and memory.

    python3 ParallelTraffic.py PLUGIN [THETA PHI ROI [RANKS...]]

Runs ParallelRegionMemory.py under `mpiexec -np N pvbatch --symmetric` for each rank count
(default 1 2 4; a 2828 x 1416 sphere, 4.0M points, and an ROI radius of 0.063 of the diagonal,
about 30k vertices), three times each: the pieces alone, the setup, and the setup with ten
moves. Open MPI's monitoring component (`--mca pml_monitoring_enable 2`) counts every byte each
rank sends, point to point and collective, ParaView's own messages included. The setup's bytes
are the second run's less the first's; a move's are the third run's less the second's, over
ten. Prints the first rank's lines and one JSON line per rank count.

With LAPLACIAN_TRAFFIC_LIMIT=F set, it fails if the setup or a move moves more than F of the
surface's size, taken as 100 bytes a point (coordinates, normals and two triangles); with
LAPLACIAN_MOVE_LIMIT=B, if a move sends more than B bytes. LAPLACIAN_EDIT_MODE picks the
rotation mode (ParallelRegionMemory.py's MODE; none by default)."""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
plugin = sys.argv[1]
theta, phi, roi = (sys.argv[2:5] if len(sys.argv) > 4 else ("2828", "1416", "0.063"))
rank_counts = [int(n) for n in sys.argv[5:]] or [1, 2, 4]
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(ranks, moves):
    """(bytes sent by all ranks, the first rank's line)."""
    with tempfile.TemporaryDirectory() as folder:
        prefix = os.path.join(folder, "traffic")
        command = ["mpiexec", "-np", str(ranks), "--oversubscribe", "--output-filename", folder,
                   "--mca", "pml_monitoring_enable", "2",
                   "--mca", "pml_monitoring_enable_output", "3",
                   "--mca", "pml_monitoring_filename", prefix,
                   "pvbatch", "--symmetric", os.path.join(here, "ParallelRegionMemory.py"),
                   plugin, theta, phi, roi, str(moves), mode]
        subprocess.run(command, env=environment, capture_output=True, check=True)
        with open(glob.glob(os.path.join(folder, "*", "rank.0", "stdout"))[0]) as lines:
            first = next((line for line in lines if line.startswith("rank 0:")), "")
        sent = 0
        for profile in glob.glob(prefix + ".*.prof"):
            with open(profile) as lines:
                # "E|I|C <from> <to> <bytes> bytes <count> msgs sent": external and internal
                # point to point, and collectives; the per-communicator lines repeat them.
                sent += sum(int(m.group(1)) for m in
                            re.finditer(r"^[EIC]\t\d+\t\d+\t(\d+) bytes", lines.read(), re.M))
    return sent, first


mode = os.environ.get("LAPLACIAN_EDIT_MODE", "none")
limit = float(os.environ.get("LAPLACIAN_TRAFFIC_LIMIT", "inf"))
move_limit = float(os.environ.get("LAPLACIAN_MOVE_LIMIT", "inf"))
failed = False
for ranks in rank_counts:
    base, _ = run(ranks, -1)
    setup, _ = run(ranks, 0)
    moved, line = run(ranks, 10)
    print(line.strip(), flush=True)
    numbers = dict(re.findall(r"(peak|setup|a move) ([\d.]+)", line))
    points = int(theta) * (int(phi) - 2) + 2
    if max(setup - base, (moved - setup) / 10.0) > limit * 100 * points:
        print(f"FAILED: {ranks} ranks moved more than {limit} of the surface", flush=True)
        failed = True
    if (moved - setup) / 10.0 > move_limit:
        print(f"FAILED: a move on {ranks} ranks sent {(moved - setup) / 10.0:.0f} bytes, more "
              f"than {move_limit:.0f}", flush=True)
        failed = True
    print(json.dumps({"ranks": ranks, "mode": mode, "points": points,
                      "roi_vertices": int(re.search(r"'NumberOfROIVertices': (\d+)", line).group(1)),
                      "setup_bytes": setup - base, "bytes_per_move": (moved - setup) / 10.0,
                      "first_rank_peak_mb": float(numbers["peak"]),
                      "setup_seconds": float(numbers["setup"]), "move_ms": float(numbers["a move"])}),
          flush=True)
sys.exit(1 if failed else 0)
