"""The volume filter's settle against OpenFOAM's mesh motion on the same boundary motion.

VolumeEditBenchmark edits a tetgen mesh (--write keeps its rest and edited meshes); OpenFOAM's
moveMesh then moves the rest mesh with displacementLaplacian, its boundary fixed to the edit,
PCG with DIC to --tolerance. Prints one JSON line per method: seconds and inverted tetrahedra,
and moveMesh's PCG iterations and peak memory (the filter's is VolumeEditBenchmark's). Needs
Debian's openfoam, python3-vtk9 and python3-numpy: a measurement, not a test.

  PYTHONPATH=build/vtk/lib/python3/dist-packages /usr/bin/python3 \\
    Testing/Benchmarks/OpenFOAMMeshMotion.py ../shared/data --meshes homer:60 \\
    --switches pq1.4a0.00000008 [--tolerance 1e-8] [--diffusivity uniform] [--work DIR]

The work directory (build/foam-mesh-motion) keeps the meshes and the OpenFOAM case.
"""
import argparse
import json
import os
import re
import subprocess
import time

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

FOAM_ENVIRONMENT = "/usr/share/openfoam/etc/bashrc"


def foam(case, command):
    """Runs an OpenFOAM command in `case`; returns its output and wall seconds."""
    start = time.perf_counter()
    run = subprocess.run(["bash", "-c", f"source {FOAM_ENVIRONMENT} >/dev/null 2>&1; {command}"],
                         cwd=case, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if run.returncode != 0:
        raise RuntimeError(f"{command} failed in {case}:\n{run.stdout[-2000:]}{run.stderr[-2000:]}")
    return run.stdout + run.stderr, seconds


def read_grid(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def foam_entries(path):
    """The entries of an ASCII OpenFOAM list file, as the strings between its outer parentheses."""
    text = open(path).read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    header = re.search(r"\n\s*(\d+)\s*\n\s*\(", text)
    return text[header.end():], int(header.group(1))


def foam_points(path):
    body, count = foam_entries(path)
    return np.array([p.split() for p in re.findall(r"\(([^()]+)\)", body)[:count]], float)


def dictionary(name, body, cls="dictionary"):
    return f"FoamFile {{ version 2.0; format ascii; class {cls}; object {name}; }}\n{body}"


def write_case(case, rest, tolerance, diffusivity):
    os.makedirs(f"{case}/system", exist_ok=True)
    os.makedirs(f"{case}/constant", exist_ok=True)
    os.makedirs(f"{case}/0", exist_ok=True)
    writer = vtk.vtkUnstructuredGridWriter()
    writer.SetFileName(f"{case}/rest.vtk")
    writer.SetInputData(rest)
    writer.SetFileTypeToASCII()
    writer.SetFileVersion(42)  # vtkUnstructuredToFoam reads the legacy format before 5.1
    writer.Write()
    files = {
        "system/controlDict": dictionary("controlDict", """application moveMesh;
startFrom startTime; startTime 0; stopAt endTime; endTime 1; deltaT 1;
writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 17;
writeCompression off; timeFormat general; timePrecision 6; runTimeModifiable false;
"""),
        "system/fvSchemes": dictionary("fvSchemes", """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; }
laplacianSchemes { default Gauss linear uncorrected; }
interpolationSchemes { default linear; }
snGradSchemes { default uncorrected; }
"""),
        "system/fvSolution": dictionary("fvSolution", f"""solvers
{{ cellDisplacement {{ solver PCG; preconditioner DIC; tolerance {tolerance}; relTol 0; }} }}
"""),
        "constant/dynamicMeshDict": dictionary("dynamicMeshDict", f"""dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolverLibs ("libfvMotionSolvers.so");
motionSolver displacementLaplacian;
displacementLaplacianCoeffs {{ diffusivity {diffusivity}; }}
"""),
    }
    for name, text in files.items():
        with open(f"{case}/{name}", "w") as out:
            out.write(text)


def fix_boundary(case, rest_points, edited_points):
    """The imported mesh's one boundary patch gets the edit's displacement, in the patch's
    point order (first appearance along its faces)."""
    boundary = open(f"{case}/constant/polyMesh/boundary").read()
    patch = re.search(r"\(\s*(\w+)\s*\{", boundary).group(1)
    start = int(re.search(r"startFace\s+(\d+)", boundary).group(1))
    count = int(re.search(r"nFaces\s+(\d+)", boundary).group(1))
    body, _ = foam_entries(f"{case}/constant/polyMesh/faces")
    faces = re.findall(r"\d+\(([\d ]+)\)", body)[start:start + count]
    order = list(dict.fromkeys(int(v) for face in faces for v in face.split()))
    imported = foam_points(f"{case}/constant/polyMesh/points")
    if np.abs(imported - rest_points).max() > 1e-9 * np.ptp(rest_points):
        raise RuntimeError("vtkUnstructuredToFoam renumbered the points")
    moves = edited_points[order] - rest_points[order]
    values = "\n".join("(%.17g %.17g %.17g)" % tuple(m) for m in moves)
    with open(f"{case}/0/pointDisplacement", "w") as out:
        out.write(dictionary("pointDisplacement", f"""dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField {{ {patch} {{ type fixedValue; value nonuniform List<vector> {len(order)}
(
{values}
); }} }}
""", "pointVectorField"))


def set_write_format(case, form):
    path = f"{case}/system/controlDict"
    text = open(path).read()
    with open(path, "w") as out:
        out.write(re.sub(r"writeFormat \w+;", f"writeFormat {form};", text))


def signed_volumes(points, tetrahedra):
    a, b, c, d = (points[tetrahedra[:, k]] for k in range(4))
    return np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("data")
    parser.add_argument("--meshes", default="homer:60")
    parser.add_argument("--switches", default="pq1.4a0.0005")
    parser.add_argument("--tolerance", default="1e-8")
    parser.add_argument("--diffusivity", default="uniform")
    parser.add_argument("--work", default="build/foam-mesh-motion")
    parser.add_argument("--benchmark", default="build/vtk/bin/VolumeEditBenchmark")
    options = parser.parse_args()
    os.makedirs(options.work, exist_ok=True)
    edit = subprocess.run([options.benchmark, options.data, "--meshes", options.meshes, "--switches",
                           options.switches, "--drags", "0", "--write", options.work],
                          capture_output=True, text=True, check=True)
    labels = []
    for line in edit.stdout.splitlines():
        result = json.loads(line)
        if result["method"] == "filter":
            labels.append(result["mesh"])
            print(json.dumps({"mesh": result["mesh"], "method": "filter",
                              "tetrahedra": result["tetrahedra"], "inverted": result["inverted"],
                              "seconds": result["seconds"]}), flush=True)
    for label, mesh in zip(labels, options.meshes.split(",")):
        name = mesh.split(":")[0]
        rest = read_grid(f"{options.work}/{name}-rest.vtu")
        edited = read_grid(f"{options.work}/{name}-edited.vtu")
        rest_points = vtk_to_numpy(rest.GetPoints().GetData()).astype(float)
        edited_points = vtk_to_numpy(edited.GetPoints().GetData()).astype(float)
        tetrahedra = vtk_to_numpy(rest.GetCells().GetConnectivityArray()).reshape(-1, 4)
        case = f"{options.work}/{name}-foam"
        subprocess.run(["rm", "-rf", case], check=True)
        write_case(case, rest, options.tolerance, options.diffusivity)
        foam(case, "vtkUnstructuredToFoam rest.vtk")
        fix_boundary(case, rest_points, edited_points)
        # moveMesh reads and writes binary, so that its time is the motion's, not the parsing's.
        set_write_format(case, "binary")
        foam(case, "foamFormatConvert -constant")
        log, seconds = foam(case, "/usr/bin/time -f 'peak %M kB' moveMesh")
        iterations = [int(n) for n in re.findall(r"No Iterations (\d+)", log)]
        set_write_format(case, "ascii")
        foam(case, "foamFormatConvert -time 1")
        moved = foam_points(f"{case}/1/polyMesh/points")
        flipped = np.sign(signed_volumes(moved, tetrahedra)) != np.sign(
            signed_volumes(rest_points, tetrahedra))
        peak = int(re.search(r"peak (\d+) kB", log).group(1)) / 1024.0
        print(json.dumps({"mesh": label, "method": f"openfoam_moveMesh_{options.diffusivity}",
                          "tetrahedra": len(tetrahedra), "inverted": int(flipped.sum()),
                          "seconds": round(seconds, 2), "pcg_iterations": iterations,
                          "tolerance": float(options.tolerance),
                          "peak_memory_mb": round(peak, 1)}), flush=True)


if __name__ == "__main__":
    main()
