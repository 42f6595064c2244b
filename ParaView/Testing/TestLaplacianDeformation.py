"""pvpython: load the plugin, edit a sphere, check the geometry, compare a screenshot.

    pvpython TestLaplacianDeformation.py PLUGIN BASELINE.png OUTPUT.png
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview import servermanager  # noqa: E402
from paraview.simple import LoadPlugin, SaveScreenshot  # noqa: E402

LoadPlugin(sys.argv[1], remote=False)
import LaplacianDeformationScene as scene  # noqa: E402

failures = []
deform = scene.edit()
deform.UpdatePipeline()
rest = servermanager.Fetch(deform.Input)
edited = servermanager.Fetch(deform)
roles = edited.GetPointData().GetArray("EditRole")
handles = moved_outside = 0
for i in range(rest.GetNumberOfPoints()):
    p, q = rest.GetPoint(i), edited.GetPoint(i)
    if roles.GetValue(i) == 0 and p != q:
        moved_outside += 1
    if roles.GetValue(i) == 3:
        handles += 1
        # rotation by 25 degrees about x through the centre (0, 0, 0.5), then the translation
        a = math.radians(25.0)
        y, z = p[1], p[2] - 0.5
        target = (p[0], y * math.cos(a) - z * math.sin(a) + 0.1, y * math.sin(a) + z * math.cos(a) + 0.5 + 0.3)
        if math.dist(q, target) > 2e-3:
            failures.append(f"handle point {i} at {q}, expected {target}")
if handles == 0:
    failures.append("no handle points")
if moved_outside:
    failures.append(f"{moved_outside} points outside the region moved")
print(f"{handles} handle points on target; outside untouched; {deform.ListProperties()}")

view = scene.show(deform)
SaveScreenshot(sys.argv[3], view, ImageResolution=[600, 500])
failures += scene.compare_with_baseline(sys.argv[3], sys.argv[2], 0.05)

for failure in failures:
    print("FAILED:", failure)
print("passed" if not failures else "failed", flush=True)
# Skip ParaView's teardown: under Xvfb, Mesa's GLX reports a bad context while the render
# window is destroyed at exit, which would turn a passed test into a failed exit status.
os._exit(1 if failures else 0)
