"""ParaView GUI test, run as `paraview --plugins=LaplacianEditing --script=TestGUI.py` with
LAPLACIAN_GUI_OUTPUT, LAPLACIAN_GUI_BASELINE and LAPLACIAN_TESTING_DIR (this folder: the GUI's
script has no __file__) set. In the GUI's own Python: apply Laplacian Deformation to a sphere and
move the handle through its properties; compare the render view, with the project's handle
widget in it, with the baseline; then drive that widget with mouse events sent to the view's
interactor, as Qt would:
  - a drag of the sphere moves the handle with the cursor, and, once applied, the output's
    handle points, with no refactorization; with Auto Apply, the filter's Dragging is on during
    the drag (a few ARAP iterations a frame) and off after it, and the widget's preview draws
    the moving surface (the view mid-drag shows what it shows once applied, not the surface of
    before), and the applied result is pvbatch's for the same properties;
  - a sweep along the handle's z ring (not the view axis) turns it by the angle swept;
  - a click on the surface puts the handle centre on the clicked point and commits the edit;
  - in array mode with a second handle group, that group's own handle appears at its centroid,
    and a drag of it moves the group's points (HandleGroupMotions) with the cursor.
Quits with the result (and writes it to LAPLACIAN_GUI_OUTPUT.result)."""
import math
import os
import sys
import traceback

output, baseline = os.environ["LAPLACIAN_GUI_OUTPUT"], os.environ["LAPLACIAN_GUI_BASELINE"]
sys.path.insert(0, os.environ["LAPLACIAN_TESTING_DIR"])
import ViewEvents as gui  # noqa: E402

checks = gui.Checks(output)
say, check = checks.say, checks.check
try:
    from paraview.simple import (GetActiveViewOrCreate, GetSettingsProxy, Render, ResetCamera,
                                 SaveScreenshot)
    import LaplacianDeformationScene as scene

    deform = scene.edit()
    view = scene.show(deform, GetActiveViewOrCreate("RenderView"))
    for step in range(1, 4):
        deform.HandleTranslation = [0.0, 0.05 * step, 0.1 * step]
        Render(view)
    SaveScreenshot(output, view, ImageResolution=[600, 500])
    # A GUI rendering may differ a little from pvpython's: a looser threshold than VTK's 0.05.
    for failure in scene.compare_with_baseline(output, baseline, 1.0):
        checks.fail(failure)

    def info(name):
        deform.UpdatePropertyInformation()
        return deform.GetProperty(name).SMProperty.GetElement(0)

    events = gui.ViewEvents(view)
    renderer, display, send = events.renderer, events.display, events.send

    renders = [0]
    view.GetRenderWindow().AddObserver("EndEvent", lambda *_: renders.__setitem__(0, renders[0] + 1))

    dragging = []  # the filter's Dragging after each move of the last drag
    previewed = []  # whether the handle widget's preview showed, after each move
    released = [0]  # the renders of the last drag's release

    def drag(path, steps=12, before_release=None):
        """Returns the number of renders during the moves."""
        send("MouseMoveEvent", path(0.0))
        send("LeftButtonPressEvent", path(0.0))
        renders[0] = 0
        dragging.clear()
        previewed.clear()
        widget = gui.handle_widgets(view)[0]
        for k in range(1, steps + 1):
            send("MouseMoveEvent", path(k / steps))
            dragging.append(info("Dragging"))
            widget.UpdatePropertyInformation()
            previewed.append(widget.GetProperty("PreviewShownInfo").GetElement(0))
        during = renders[0]
        if before_release:
            before_release()
        before = renders[0]
        send("LeftButtonReleaseEvent", path(1.0))
        released[0] = renders[0] - before
        return during

    def unchecked(name):
        return gui.unchecked(deform, name)

    def apply():
        for name in ("HandleCenter", "HandleTranslation", "HandleRotation"):
            deform.SetPropertyWithName(name, unchecked(name))
        Render(view)

    def handle_points_center():
        edited = deform.GetClientSideObject().GetOutput()
        roles = edited.GetPointData().GetArray("EditRole")
        points = [edited.GetPoint(i) for i in range(edited.GetNumberOfPoints()) if roles.GetValue(i) == 3]
        return [sum(p[i] for p in points) / len(points) for i in range(3)]

    def check_preview_and_pvbatch():
        """The last drag's view mid-drag against the applied one and the one before, and the
        applied surface against pvbatch's for the same properties."""
        SaveScreenshot(output + ".applied.png", view, ImageResolution=[600, 500])
        differs = scene.compare_with_baseline(output + ".preview.png", output + ".before.png", 1.0)
        same = scene.compare_with_baseline(output + ".preview.png", output + ".applied.png", 1.0)
        check(not same and differs, f"mid-drag, the view shows the applied surface ({same}), "
              f"not the surface of before ({'differs' if differs else 'the same'})")
        scripted = gui.scripted_points(gui.applied_properties(deform))
        edited = deform.GetClientSideObject().GetOutput()
        worst = max(math.dist(edited.GetPoint(i), p) for i, p in enumerate(scripted))
        check(len(scripted) == edited.GetNumberOfPoints() and worst < 1e-9,
              f"the applied drag's surface is pvbatch's for its properties (largest distance {worst:.1e})")

    # Closer, looking at the handle, for the drags.
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(*[c + t for c, t in zip(deform.HandleCenter, deform.HandleTranslation)])
    camera.Dolly(2.5)
    renderer.ResetCameraClippingRange()
    Render(view)

    # 1. Drag the sphere 40 pixels up.
    factorizations = info("NumberOfFactorizations")
    say(f"before the drag: {factorizations} factorizations, centre {unchecked('HandleCenter')}, "
        f"radii {unchecked('HandleRadius')} {unchecked('ROIRadius')}")
    center = [c + t for c, t in zip(deform.HandleCenter, deform.HandleTranslation)]
    before = handle_points_center()
    at = display(center)
    # With Auto Apply, which renders each applied move, the widget does not render the view too.
    settings = GetSettingsProxy("GeneralSettings")
    settings.AutoApply = 1
    SaveScreenshot(output + ".before.png", view, ImageResolution=[600, 500])
    during = drag(lambda t: (at[0], at[1] + 40.0 * t),
                  before_release=lambda: SaveScreenshot(output + ".preview.png", view, ImageResolution=[600, 500]))
    settings.AutoApply = 0
    check(during == 0 and released[0] == 0 and view.GetProperty("EnableRenderOnInteraction").GetData() == 0,
          f"with Auto Apply, the drag leaves rendering to it ({during} renders), and so does the release "
          f"({released[0]} renders), the preview showing until the update that applies the drag")
    check(dragging == [1] * 12 and info("Dragging") == 0,
          f"and turns the filter's Dragging on during it ({dragging}), off after it")
    check(previewed == [1] * 12, f"the widget's preview draws every move ({previewed})")
    translation = unchecked("HandleTranslation")
    moved = [c + t for c, t in zip(unchecked("HandleCenter"), translation)]
    landed = display(moved)
    say(f"drag: handle centre now at {landed}, cursor at {(at[0], at[1] + 40.0)}")
    check(abs(landed[0] - at[0]) < 2.0 and abs(landed[1] - at[1] - 40.0) < 2.0,
          "a drag of the sphere moves the handle with the cursor (2 pixels)")
    say(f"after the drag: centre {unchecked('HandleCenter')}, radii {unchecked('HandleRadius')} "
        f"{unchecked('ROIRadius')}, translation {translation}")
    apply()
    check(view.GetProperty("EnableRenderOnInteraction").GetData() == 1 and not gui.handle_widgets(view)[0]
          .GetProperty("Previewing").GetElement(0),
          "that update ends the preview and gives the view back its renders on interaction")
    after = handle_points_center()
    shift = [a - b for a, b in zip(after, before)]
    expected = [m - c for m, c in zip(moved, center)]
    check(max(abs(s - e) for s, e in zip(shift, expected)) < 2e-3,
          f"the output's handle points follow the drag once applied ({shift} for {expected})")
    check(info("NumberOfFactorizations") == factorizations, "the drag does not refactor")
    check_preview_and_pvbatch()

    # 2. Turn about the handle's x axis, 40 degrees from the view direction: sweep 40 degrees
    #    along the x ring, from its point in front of the sphere and outside its disc.
    deform.HandleRotation = [0.0, 0.0, 0.0]
    Render(view)
    center = [c + t for c, t in zip(deform.HandleCenter, deform.HandleTranslation)]
    ring = 1.15 * deform.HandleRadius
    direction = [f - p for f, p in zip(camera.GetFocalPoint(), camera.GetPosition())]

    def ring_point(degrees):  # in the y-z plane, from y toward z
        a = math.radians(degrees)
        return [center[0], center[1] + ring * math.cos(a), center[2] + ring * math.sin(a)]

    def score(degrees):
        a = math.radians(degrees)
        front = math.cos(a) * direction[1] + math.sin(a) * direction[2] < 0.0
        near_other_ring = min(abs(math.cos(a)), abs(math.sin(a))) < 0.6
        p, c = display(ring_point(degrees)), display(center)
        return math.dist(p, c) if front and not near_other_ring else -1.0

    start = max(range(0, 360, 5), key=score)
    say(f"turn from {start} degrees, centre {center}, display {display(center)}, start {display(ring_point(start))}")
    during = drag(lambda t: display(ring_point(start + 40.0 * t)), steps=20)
    check(during > 0, f"without Auto Apply, the widget renders its moves ({during} renders)")
    rotation = unchecked("HandleRotation")
    say(f"turn: HandleRotation {rotation}")
    check(abs(rotation[0] - 40.0) < 3.0 and abs(rotation[1]) < 3.0 and abs(rotation[2]) < 3.0,
          "a 40-degree sweep along the x ring turns the handle 40 degrees about x (3 degrees)")
    apply()
    check(info("NumberOfFactorizations") == factorizations, "the turn does not refactor")

    # 3. Click the surface low on the sphere, outside the region: the handle goes there, and the
    #    edit in progress is committed first.
    ResetCamera(view)
    Render(view)
    target = [0.357, -0.288, -0.198]
    at = display(target)
    send("MouseMoveEvent", at)
    send("LeftButtonPressEvent", at)
    send("LeftButtonReleaseEvent", at)
    placed = unchecked("HandleCenter")
    say(f"click: HandleCenter {placed}")
    check(math.dist(placed, target) < 0.05, "a click on the surface puts the handle centre there")
    check(unchecked("HandleTranslation") == [0.0, 0.0, 0.0] and unchecked("HandleRotation") == [0.0, 0.0, 0.0],
          "the new handle starts at rest")
    check(info("NumberOfCommits") == 1, "the edit in progress was committed")

    # 4. Array mode with two handle groups: the north cap (label 2) and a patch on the equator
    #    (label 3), in an ROI of the upper half. Drag the second group's own handle 40 pixels up.
    from paraview import servermanager
    from paraview.simple import Hide, SetActiveSource, Show, TrivialProducer, LaplacianDeformation
    from vtkmodules.vtkCommonCore import vtkIntArray

    rest = servermanager.Fetch(deform.Input)
    labeled = rest.NewInstance()
    labeled.ShallowCopy(rest)
    labels = vtkIntArray()
    labels.SetName("Labels")
    group = []
    for i in range(rest.GetNumberOfPoints()):
        x, y, z = rest.GetPoint(i)
        label = 2 if z > 0.45 else (3 if abs(z) < 0.06 and x > 0.3 and abs(y) < 0.15 else (1 if z > -0.3 else 0))
        labels.InsertNextValue(label)
        if label == 3:
            group.append(i)
    labeled.GetPointData().AddArray(labels)
    producer = TrivialProducer()
    producer.GetClientSideObject().SetOutput(labeled)
    Hide(deform, view)
    groups = LaplacianDeformation(Input=producer, SelectionMode="Array", SelectionArray=["POINTS", "Labels"])
    deform = groups  # for info() and unchecked()
    scene.role_colors(Show(groups, view))
    SetActiveSource(groups)
    Render(view)
    check(info("NumberOfHandleGroups") == 2, f"the filter reports two handle groups ({info('NumberOfHandleGroups')})")
    centroid = [sum(rest.GetPoint(i)[k] for i in group) / len(group) for k in range(3)]
    ResetCamera(view)
    camera.SetFocalPoint(*centroid)
    camera.Dolly(2.5)
    renderer.ResetCameraClippingRange()
    Render(view)

    def group_points_center():
        edited = groups.GetClientSideObject().GetOutput()
        return [sum(edited.GetPoint(i)[k] for i in group) / len(group) for k in range(3)]

    before = group_points_center()
    factorizations = info("NumberOfFactorizations")
    at = display(centroid)
    settings.AutoApply = 1
    drag(lambda t: (at[0], at[1] + 40.0 * t))
    settings.AutoApply = 0
    motions = unchecked("HandleGroupMotions")
    say(f"group drag: HandleGroupMotions {motions}, group of {len(group)} points at {centroid}")
    check(len(motions) == 7 and motions[0] == 1.0, "the drag gives group 1 a motion")
    if len(motions) == 7:
        landed = display([c + t for c, t in zip(centroid, motions[1:4])])
        check(abs(landed[0] - at[0]) < 2.0 and abs(landed[1] - at[1] - 40.0) < 2.0,
              f"a drag of the group's handle moves it with the cursor ({landed} for {(at[0], at[1] + 40.0)})")
        groups.HandleGroupMotions = motions
        Render(view)
        shift = [a - b for a, b in zip(group_points_center(), before)]
        check(max(abs(s - e) for s, e in zip(shift, motions[1:4])) < 2e-3,
              f"the group's points follow its handle once applied ({shift} for {motions[1:4]})")
    check(info("NumberOfFactorizations") == factorizations, "the group drag does not refactor")

    def enabled_handles():
        return len(gui.handle_widgets(view))

    check(enabled_handles() == 2, f"the view shows a handle for each group ({enabled_handles()})")
    groups.SelectionMode = "Geodesic"
    groups.HandleCenter = [0.0, 0.0, 0.5]
    groups.HandleRadius, groups.ROIRadius = 0.1, 0.6
    Render(view)
    check(info("NumberOfHandleGroups") == 1 and enabled_handles() == 1,
          f"without the groups, their handles leave the view ({info('NumberOfHandleGroups')} groups, "
          f"{enabled_handles()} handles)")
except Exception:  # any error must end the run, not open a modal dialog that never closes
    checks.fail(traceback.format_exc())
checks.finish()
