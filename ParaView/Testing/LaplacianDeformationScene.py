"""The ParaView tests' shared scene (a sphere with its north pole lifted and turned) and image
comparison."""
import os
import paraview.simple as simple
from paraview.simple import GetActiveViewOrCreate, Render, ResetCamera, Show, Sphere


def edit(rotation_mode="Explicit"):
    sphere = Sphere(ThetaResolution=64, PhiResolution=48)
    deform = simple.LaplacianDeformation(Input=sphere)  # from the loaded plugin
    deform.HandleCenter = [0.0, 0.0, 0.5]
    deform.HandleRadius = 0.1
    deform.ROIRadius = 0.9
    deform.HandleTranslation = [0.0, 0.1, 0.3]
    deform.HandleRotation = [25.0, 0.0, 0.0]
    deform.RotationMode = rotation_mode
    return deform


def show(deform, view=None):
    if view is None:
        view = GetActiveViewOrCreate("RenderView")
        view.ViewSize = [600, 500]
    view.OrientationAxesVisibility = 0
    display = Show(deform, view)
    display.ColorArrayName = ["POINTS", "EditRole"]
    role_colors(display)
    view.CameraPosition = [2.5, -2.0, 1.2]
    view.CameraFocalPoint = [0.0, 0.0, 0.2]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    return view


def role_colors(display):
    """Colours `display` by EditRole with a categorical map of the paper's Fig. 2 colours."""
    lut = simple.GetColorTransferFunction("EditRole")
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = ["0", "fixed", "1", "anchor", "2", "free", "3", "handle"]
    lut.IndexedColors = [0.75, 0.75, 0.75, 0.85, 0.20, 0.15, 0.35, 0.75, 0.35, 0.95, 0.85, 0.10]
    display.LookupTable = lut


def compare_with_baseline(image, baseline, threshold):
    """The failures, if any, of `image` against `baseline` (VTK's thresholded image error)."""
    from vtkmodules.vtkImagingCore import vtkImageDifference
    from vtkmodules.vtkIOImage import vtkPNGReader

    if not os.path.exists(baseline):
        return [f"no baseline at {baseline} (this run's image: {image})"]
    readers = []
    for path in (baseline, image):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        readers.append(reader)
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[1].GetOutputPort())
    difference.SetImageConnection(readers[0].GetOutputPort())
    difference.Update()
    error = difference.GetThresholdedError()
    print(f"image error {error} (threshold {threshold})", flush=True)
    return [] if error <= threshold else [f"{image} differs from {baseline}: {error}"]
