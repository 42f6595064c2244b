"""ParaView GUI test of the landmark dragger, run as `paraview --plugins=LaplacianEditing
--script=TestGUILandmarks.py` with LAPLACIAN_GUI_OUTPUT, LAPLACIAN_TESTING_DIR and
LAPLACIAN_DATA_DIR set. In the GUI's own Python: the bunny warped by the committed landmark table
(200 landmarks, Examples/Data/bunny-landmarks.csv); the Landmark Drag panel's handle sits on
landmark 0's target; a drag of it with mouse events and Auto Apply turns the warp's Dragging on
during the drag and off after it, and moves that target (MovedTargets); applied, the warp
reuses its factorization and meets the moved target. Then a settle that the time limit cuts:
the panel gives the warp its half-second limit; with a limit every step reaches, the update
after a new move stops after one step, the warp settling, and once this script returns the panel
continues the settle between the GUI's events, one step an update, every landmark met at each,
until it ends within 1% of the converged energy (a warp's on the same targets, run to
convergence). Quits with the result (and writes it to LAPLACIAN_GUI_OUTPUT.result)."""
import math
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
    from paraview.simple import GetActiveViewOrCreate, GetSettingsProxy, Render, SaveScreenshot, Show

    surface = simple.OpenDataFile(os.path.join(os.environ["LAPLACIAN_DATA_DIR"], "stanford-bunny.obj"))
    table = simple.CSVReader(FileName=[os.path.join(
        os.environ["LAPLACIAN_TESTING_DIR"], "..", "..", "Examples", "Data", "bunny-landmarks.csv")])
    points = simple.TableToPoints(Input=table, XColumn="x", YColumn="y", ZColumn="z")
    landmarks = simple.Calculator(Input=points, ResultArrayName="Target",
                                  Function="tx*iHat + ty*jHat + tz*kHat")
    warp = simple.LaplacianLandmarkWarp(Input=surface, Landmarks=landmarks)
    warp.TargetArray = ["POINTS", "Target"]
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [600, 500]
    view.OrientationAxesVisibility = 0
    Show(warp, view)  # the panel shows the active source's widgets while the source is shown
    simple.SetActiveSource(warp)
    view.ResetCamera()
    Render(view)

    def info(name, element=0):
        warp.UpdatePropertyInformation()
        return warp.GetProperty(name).SMProperty.GetElement(element)

    hidden = view.SMProxy.GetProperty("HiddenRepresentations")
    handles = [hidden.GetProxy(k) for k in range(hidden.GetNumberOfProxies())]
    handles = [h for h in handles if h.GetXMLName() == "HandleWidgetRepresentation"
               and h.GetProperty("Enabled").GetElement(0)]
    check(len(handles) == 1, f"the landmark handle is in the view ({len(handles)})")
    check(info("SettleTimeLimitInfo") == 0.5, "the panel gives the warp its settle time limit")
    handle = handles[0]
    target = [info("WarpedTargets", c) for c in range(3)]
    handle.UpdatePropertyInformation()
    placed = [handle.GetProperty("WorldPositionInfo").GetElement(c) for c in range(3)]
    check(math.dist(placed, target) < 1e-9, f"it sits on landmark 0's target ({placed} at {target})")

    factorizations = info("NumberOfFactorizations")
    events = gui.ViewEvents(view)
    at = events.display(target)
    settings = GetSettingsProxy("GeneralSettings")
    settings.AutoApply = 1
    events.send("MouseMoveEvent", at)
    events.send("LeftButtonPressEvent", at)
    dragging = []
    for k in range(1, 11):
        events.send("MouseMoveEvent", (at[0] + 3.0 * k, at[1] + 3.0 * k))
        dragging.append(info("Dragging"))
    events.send("LeftButtonReleaseEvent", (at[0] + 30.0, at[1] + 30.0))
    settings.AutoApply = 0
    check(dragging == [1] * 10 and info("Dragging") == 0,
          f"the warp's Dragging is on during the drag ({dragging}) and off after it")
    moved = gui.unchecked(warp, "MovedTargets")
    handle.UpdatePropertyInformation()
    dropped = [handle.GetProperty("WorldPositionInfo").GetElement(c) for c in range(3)]
    check(len(moved) == 4 and moved[0] == 0 and math.dist(moved[1:], dropped) < 1e-9,
          f"the drag moved landmark 0's target to the handle ({moved})")
    size = math.dist(dropped, target)
    say(f"landmark 0's target moved by {size:.4f}")
    check(size > 0.0, "the handle moved")
    # The panel's values, applied as Auto Apply would once the GUI's event loop runs.
    warp.SetPropertyWithName("MovedTargets", moved)
    Render(view)
    reached = [info("WarpedTargets", c) for c in range(3)]
    check(math.dist(reached, dropped) < 1e-9, f"the warp took the moved target ({reached})")
    check(info("NumberOfFactorizations") == factorizations,
          f"and reused its factorization ({factorizations} -> {info('NumberOfFactorizations')})")
    check(info("MaximumLandmarkDistance") < 1e-6, f"every landmark on its target "
          f"({info('MaximumLandmarkDistance'):.1e})")
    SaveScreenshot(output, view, ImageResolution=[600, 500])

    # The target moved halfway back, with a settle time limit that every step reaches.
    limit = warp.SMProxy.GetProperty("SettleTimeLimit")  # internal: pushed only when set
    limit.SetElement(0, 1e-9)
    warp.SMProxy.UpdateVTKObjects()
    moved = [0] + [0.5 * (d + t) for d, t in zip(dropped, target)]
    warp.SetPropertyWithName("MovedTargets", moved)
    Render(view)
    check(info("Settling") == 1 and info("NumberOfARAPIterations") == 1,
          "the update after a move stops its settle after one step, the warp settling")

    # The converged energy for the same targets: a warp run to convergence.
    reference = simple.LaplacianLandmarkWarp(Input=surface, Landmarks=landmarks)
    reference.TargetArray = ["POINTS", "Target"]
    reference.MovedTargets = moved
    best = gui.converged_energy(reference)
    simple.SetActiveSource(warp)
    gui.watch_continued_settle(checks, warp, best, [
        ("MaximumLandmarkDistance", 1e-6, "every landmark met at every update")])
    pending = not checks.failures
except Exception:  # any error must end the run, not open a modal dialog that never closes
    checks.fail(traceback.format_exc())
if not pending:
    checks.finish()
