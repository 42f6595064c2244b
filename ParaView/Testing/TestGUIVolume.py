"""ParaView GUI test of a volume, run as `paraview --plugins=LaplacianEditing
--script=TestGUIVolume.py` with LAPLACIAN_GUI_OUTPUT and LAPLACIAN_TESTING_DIR set. In the GUI's
own Python: apply Laplacian Volume Deformation to a bar cut in tetrahedra, clip it open, and drag
the project's handle widget with mouse events and Auto Apply: every move updates the pipeline
with the filter's Dragging on (a volume's drag is not previewed, so that the clip shows the
interior follow), the release settles it; the clip's interior moved with the handle, and no cell
is inverted. Then a second drag and release with a settle time limit on the server that every
iteration reaches: the release's update stops its settle, and once this script returns, the panel
continues it between the GUI's events, update by update, every cell positive at each, until it
ends with every boundary point on its target. Quits with the result (and writes it to
LAPLACIAN_GUI_OUTPUT.result)."""
import os
import sys
import traceback

output = os.environ["LAPLACIAN_GUI_OUTPUT"]
sys.path.insert(0, os.environ["LAPLACIAN_TESTING_DIR"])
import ViewEvents as gui  # noqa: E402

checks = gui.Checks(output)
say, check = checks.say, checks.check
pending = False
try:
    import paraview.simple as simple
    from paraview import servermanager
    from paraview.simple import (Clip, GetActiveViewOrCreate, GetSettingsProxy, Hide, MeshQuality,
                                 Render, SaveScreenshot, Show, Tetrahedralize, Wavelet)

    bar = Tetrahedralize(Input=Wavelet(WholeExtent=[0, 20, 0, 4, 0, 4]))
    volume = simple.LaplacianVolumeDeformation(Input=bar)
    volume.HandleCenter = [20, 2, 2]
    volume.HandleRadius = 1.5
    volume.ROIRadius = 10
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [600, 400]
    view.OrientationAxesVisibility = 0
    Show(volume, view)  # the panel shows the active source's handle while the source is shown
    view.CameraPosition = [12, -45, 2]
    view.CameraFocalPoint = [12, 2, 2]
    view.CameraViewUp = [0, 0, 1]
    Render(view)
    widgets = gui.handle_widgets(view)
    check(len(widgets) == 1, f"the volume's handle widget is in the view ({len(widgets)})")

    def info(name):
        volume.UpdatePropertyInformation()
        return volume.GetProperty(name).SMProperty.GetElement(0)

    def clip_top(source):
        """The top of the source cut open along the bar's length (a user's Clip)."""
        clip = Clip(Input=source)
        clip.ClipType.Normal = [0, 1, 0]
        clip.ClipType.Origin = [10, 2, 2]
        return clip, servermanager.Fetch(clip).GetBounds()[5]

    events = gui.ViewEvents(view)
    at = events.display([20, 2, 2])
    settings = GetSettingsProxy("GeneralSettings")
    settings.AutoApply = 1
    events.send("MouseMoveEvent", at)
    events.send("LeftButtonPressEvent", at)
    dragging, previewed = [], []
    for k in range(1, 11):
        events.send("MouseMoveEvent", (at[0], at[1] + 6.0 * k))
        dragging.append(info("Dragging"))
        widgets[0].UpdatePropertyInformation()
        previewed.append(widgets[0].GetProperty("PreviewShownInfo").GetElement(0))
    events.send("LeftButtonReleaseEvent", (at[0], at[1] + 60.0))
    settings.AutoApply = 0
    Render(view)
    check(dragging == [1] * 10 and info("Dragging") == 0,
          f"the filter's Dragging is on during the drag ({dragging}) and off after it")
    check(previewed == [0] * 10, f"the drag updates the pipeline, not a preview ({previewed})")
    # The widget's values, applied as Auto Apply would once the GUI's event loop runs.
    for name in ("HandleCenter", "HandleTranslation", "HandleRotation"):
        volume.SetPropertyWithName(name, gui.unchecked(volume, name))
    Render(view)
    lift = volume.GetPropertyValue("HandleTranslation")[2]
    before = clip_top(bar)[1]
    clip, after = clip_top(volume)
    Show(clip, view)
    Hide(volume, view)
    say(f"handle lifted {lift:.2f}; the clip's top {before:.2f} -> {after:.2f}")
    check(lift > 1.0 and after > before + 0.5 * lift,
          "the clip of the volume shows the edit (its top rises with the handle)")
    quality = MeshQuality(Input=volume)
    quality.TetQualityMeasure = "Scaled Jacobian"
    smallest = servermanager.Fetch(quality).GetCellData().GetArray("Quality").GetRange()[0]
    check(smallest > 0, f"no cell inverted (smallest scaled Jacobian {smallest:.3f})")
    check(info("NumberOfFailedCells") == 0, "every boundary point reached its edit")
    Render(view)
    SaveScreenshot(output, view, ImageResolution=[600, 400])

    # The release settles in steps between the GUI's events, as a large one would.
    check(info("SettleTimeLimitInfo") == 0.5, "the panel gives the filter its settle time limit")
    limit = volume.SMProxy.GetProperty("SettleTimeLimit")  # internal: pushed only when set
    limit.SetElement(0, 1e-9)  # every iteration reaches it
    volume.SMProxy.UpdateVTKObjects()
    Show(volume, view)
    Render(view)
    at = events.display([20, 2, 2 + lift])
    settings.AutoApply = 1
    events.send("MouseMoveEvent", at)
    events.send("LeftButtonPressEvent", at)
    for k in range(1, 6):
        events.send("MouseMoveEvent", (at[0] + 6.0 * k, at[1]))
    events.send("LeftButtonReleaseEvent", (at[0] + 30.0, at[1]))
    for name in ("HandleCenter", "HandleTranslation", "HandleRotation"):
        volume.SetPropertyWithName(name, gui.unchecked(volume, name))
    Render(view)
    settings.AutoApply = 0
    check(info("Settling") == 1, "the release's update stops its settle, the filter settling")
    filter = volume.GetClientSideObject()  # the built-in session's (its VTK base class)
    smallest = []

    def continued(caller, event):
        try:
            jacobians = filter.GetOutput().GetCellData().GetArray("ScaledJacobian")
            smallest.append(jacobians.GetRange()[0])
            if info("Settling"):
                return
            say(f"settle continued in {len(smallest)} updates; smallest scaled Jacobian "
                f"{min(smallest):.3f}")
            check(len(smallest) >= 2, "the panel continues the settle between the events")
            check(min(smallest) > 0, "every cell positive at every update")
            check(info("NumberOfFailedCells") == 0,
                  "the settle ends with every boundary point on its target")
        except Exception:
            checks.fail(traceback.format_exc())
        checks.finish()
    filter.AddObserver("EndEvent", continued)
    pending = not checks.failures
except Exception:  # any error must end the run, not open a modal dialog that never closes
    checks.fail(traceback.format_exc())
if not pending:
    checks.finish()
