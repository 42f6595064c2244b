"""ParaView GUI test of a release that settles in steps, run as `paraview
--plugins=LaplacianEditing --script=TestGUISettle.py` with LAPLACIAN_GUI_OUTPUT and
LAPLACIAN_TESTING_DIR set. In the GUI's own Python: a large region (its proxy dragged, its
release settled by Newton's steps) whose settle time limit on the server every step reaches,
dragged with mouse events and Auto Apply and released: the release's update stops after one
step, with the filter settling; once this script returns, the panel continues the settle between
the GUI's events, one step an update, until it ends, within 1% of the converged energy (a
factored filter's on the same values, run to convergence). Quits with the result (and writes it
to LAPLACIAN_GUI_OUTPUT.result)."""
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
    from paraview.simple import GetActiveViewOrCreate, GetSettingsProxy, Render
    import LaplacianDeformationScene as scene

    deform = scene.edit("As rigid as possible")
    deform.HandleTranslation = [0.0, 0.0, 0.0]
    deform.HandleRotation = [0.0, 0.0, 0.0]
    deform.LargeRegionVertices = 500
    deform.ProxyNodes = 200
    deform.ARAPIterations = 50
    view = scene.show(deform, GetActiveViewOrCreate("RenderView"))
    widgets = gui.handle_widgets(view)
    check(len(widgets) == 1, f"the handle widget is in the view ({len(widgets)})")
    def info(name):
        return gui.information(deform, name)

    check(info("SettleTimeLimitInfo") == 0.5, "the panel gives the filter its settle time limit")
    limit = deform.SMProxy.GetProperty("SettleTimeLimit")  # internal: pushed only when set
    limit.SetElement(0, 1e-9)  # every step reaches it
    deform.SMProxy.UpdateVTKObjects()

    events = gui.ViewEvents(view)
    at = events.display(deform.HandleCenter)
    settings = GetSettingsProxy("GeneralSettings")
    settings.AutoApply = 1
    events.send("MouseMoveEvent", at)
    events.send("LeftButtonPressEvent", at)
    for k in range(1, 11):
        events.send("MouseMoveEvent", (at[0], at[1] + 6.0 * k))
    events.send("LeftButtonReleaseEvent", (at[0], at[1] + 60.0))
    # The widget's values, applied as Auto Apply would once the GUI's event loop runs.
    for name in ("HandleCenter", "HandleTranslation", "HandleRotation"):
        deform.SetPropertyWithName(name, gui.unchecked(deform, name))
    Render(view)
    settings.AutoApply = 0
    lift = max(abs(c) for c in deform.GetPropertyValue("HandleTranslation"))
    check(lift > 0.05, f"the drag moved the handle ({lift:.3f})")
    check(info("Settling") == 1 and info("NumberOfARAPIterations") == 1,
          "the release's update stops its settle after one step, the filter settling")

    # The converged energy at the same values: a factored filter run to convergence.
    reference = simple.LaplacianDeformation(Input=deform.Input)
    for name in ("HandleCenter", "HandleRadius", "ROIRadius", "HandleTranslation", "HandleRotation",
                 "RotationMode"):
        reference.SetPropertyWithName(name, deform.GetPropertyValue(name))
    reference.LargeRegionVertices = 0
    best = gui.converged_energy(reference)
    simple.SetActiveSource(deform)
    gui.watch_continued_settle(checks, deform, best)
    pending = not checks.failures
except Exception:  # any error must end the run, not open a modal dialog that never closes
    checks.fail(traceback.format_exc())
if not pending:
    checks.finish()
