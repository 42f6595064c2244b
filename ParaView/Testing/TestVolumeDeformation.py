"""pvbatch: a volume mesh edited through the plugin: the interior follows, no cell inverts, a
clip coloured by ScaledJacobian shows it.

    pvbatch TestVolumeDeformation.py PLUGIN OUTPUT.png
"""
import sys

from paraview import servermanager
import paraview.simple as simple
from paraview.simple import (Clip, ColorBy, GetActiveViewOrCreate, LoadPlugin, MeshQuality,
                             ResetCamera, SaveScreenshot, Show, Tetrahedralize, Wavelet)

LoadPlugin(sys.argv[1], remote=False)
failures = []

# A bar of 20 x 4 x 4 cubes cut in tetrahedra; its end x = 20 turned down and lifted.
bar = Tetrahedralize(Input=Wavelet(WholeExtent=[0, 20, 0, 4, 0, 4]))
volume = simple.LaplacianVolumeDeformation(Input=bar)  # the plugin's, once loaded
volume.HandleCenter = [20, 2, 2]
volume.HandleRadius = 1.5
volume.ROIRadius = 10
volume.HandleRotation = [0, -60, 0]
volume.HandleTranslation = [0, 0, 4]
volume.UpdatePipeline()

rest = servermanager.Fetch(bar)
edited = servermanager.Fetch(volume)
moved = sum(rest.GetPoint(i) != edited.GetPoint(i) for i in range(rest.GetNumberOfPoints()))
interior = sum(rest.GetPoint(i) != edited.GetPoint(i) and 0 < rest.GetPoint(i)[1] < 4
               and 0 < rest.GetPoint(i)[2] < 4 for i in range(rest.GetNumberOfPoints()))
if interior == 0:
    failures.append("no interior point moved")
# Points beyond the region and its reach, at x < 5, keep their place.
far = [i for i in range(rest.GetNumberOfPoints()) if rest.GetPoint(i)[0] < 5]
if any(rest.GetPoint(i) != edited.GetPoint(i) for i in far):
    failures.append("a point far from the region moved")
for name in ("ScaledJacobian", "EditFailed", "RTData"):
    if not edited.GetCellData().GetArray(name) and not edited.GetPointData().GetArray(name):
        failures.append(f"no {name} array")
if edited.GetCellData().GetArray("EditFailed").GetRange()[1] != 0:
    failures.append("cells failed")

# VTK's own measure: no tetrahedron inverted.
quality = MeshQuality(Input=volume)
quality.TetQualityMeasure = "Scaled Jacobian"
smallest = servermanager.Fetch(quality).GetCellData().GetArray("Quality").GetRange()[0]
if not smallest > 0:
    failures.append(f"smallest scaled Jacobian {smallest}")

# The interior in a clip, coloured by cell quality.
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [600, 300]
clip = Clip(Input=volume)
clip.ClipType.Normal = [0, 1, 0]
clip.ClipType.Origin = [10, 2, 2]
display = Show(clip, view)
ColorBy(display, ("CELLS", "ScaledJacobian"))
view.CameraPosition = [10, -40, 2]
view.CameraFocalPoint = [10, 2, 2]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)
SaveScreenshot(sys.argv[2], view)

volume.UpdatePropertyInformation()
zone = volume.GetPropertyValue("NumberOfZonePoints")
if not zone > 0:
    failures.append("no zone reported")
print(f"{moved} points moved, {interior} inside; smallest scaled Jacobian {smallest:.3f}; "
      f"{zone} zone points")
if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("volume checked")
