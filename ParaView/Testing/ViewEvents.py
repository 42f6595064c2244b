"""Mouse events sent to a ParaView render view's interactor, as Qt would send them, and what the
panel's widget holds: helpers of the GUI tests and the GUI drag benchmark."""
import os
import time


class ViewEvents:
    def __init__(self, view):
        self.renderer, self.interactor = view.GetRenderer(), view.GetInteractor()

    def display(self, point):
        """The display position of a world point."""
        self.renderer.SetWorldPoint(point[0], point[1], point[2], 1.0)
        self.renderer.WorldToDisplay()
        return self.renderer.GetDisplayPoint()[:2]

    def send(self, name, at, control=0):
        self.interactor.SetEventInformation(int(round(at[0])), int(round(at[1])), control, 0)
        self.interactor.InvokeEvent(name)


def unchecked(proxy, name):
    """A property's unapplied values (what the panel's widget set)."""
    prop = proxy.GetProperty(name).SMProperty
    return [prop.GetUncheckedElement(i) for i in range(prop.GetNumberOfUncheckedElements())]


def handle_widgets(view):
    """The enabled handle widgets' representations in the view."""
    hidden = view.SMProxy.GetProperty("HiddenRepresentations")
    widgets = [hidden.GetProxy(k) for k in range(hidden.GetNumberOfProxies())]
    return [w for w in widgets if w.GetXMLName() == "DeformationHandleWidgetRepresentation"
            and w.GetProperty("Enabled").GetElement(0)]


def scripted_points(properties):
    """The points of the tests' scene edited with `properties` by pvbatch (ScriptedEdit.py);
    LAPLACIAN_PVBATCH, LAPLACIAN_PLUGIN and LAPLACIAN_TESTING_DIR say where things are."""
    import json
    import subprocess
    import tempfile
    with tempfile.NamedTemporaryFile(suffix=".txt") as points:
        subprocess.run([os.environ["LAPLACIAN_PVBATCH"],
                        os.path.join(os.environ["LAPLACIAN_TESTING_DIR"], "ScriptedEdit.py"),
                        os.environ["LAPLACIAN_PLUGIN"], json.dumps(properties), points.name],
                       check=True, capture_output=True)
        return [[float(c) for c in line.split()] for line in open(points.name)]


def applied_properties(deform):
    """The filter's applied handle and region properties, for scripted_points."""
    names = ("HandleCenter", "HandleRadius", "ROIRadius", "HandleTranslation", "HandleRotation")
    values = {name: deform.GetPropertyValue(name) for name in names}
    values = {k: (list(v) if hasattr(v, "__len__") else v) for k, v in values.items()}
    values["RotationMode"] = deform.GetProperty("RotationMode").GetData()
    return values


def information(proxy, name):
    """An information property's first value, fetched afresh."""
    proxy.UpdatePropertyInformation()
    return proxy.GetProperty(name).SMProperty.GetElement(0)


def converged_energy(reference):
    """The ARAP energy of `reference`, a filter on the values under test, run to convergence
    (the panel's settle time limit undone)."""
    reference.ARAPIterations = 10000
    reference.Convergence = 1e-12
    reference.SMProxy.GetProperty("SettleTimeLimit").SetElement(0, 0.0)
    reference.UpdatePipeline()
    return information(reference, "ARAPEnergy")


def watch_continued_settle(checks, proxy, best, every_update=()):
    """Once the script returns, the panel continues `proxy`'s cut settle between the GUI's
    events: observes its updates until the settle ends, then checks at least two updates of
    one step each, the last energy within 1% of `best`, and each (name, limit, what) of
    `every_update` under its limit at every update, and ends the run."""
    steps, values = [], {name: [] for name, _, _ in every_update}

    def continued(filter, event):
        try:
            steps.append(information(proxy, "NumberOfARAPIterations"))
            for name in values:
                values[name].append(information(proxy, name))
            if information(proxy, "Settling"):
                return
            energy = information(proxy, "ARAPEnergy")
            checks.say(f"settle continued in {len(steps)} updates of {steps} steps; energy over "
                       f"converged {energy / best:.6f}")
            checks.check(len(steps) >= 2, "the panel continues the settle between the events")
            checks.check(all(count == 1 for count in steps), "one step an update")
            for name, limit, what in every_update:
                checks.check(max(values[name]) < limit, f"{what} (at most {max(values[name]):.1e})")
            checks.check(best > 0.0 and energy <= 1.01 * best,
                         "the settle ends within 1% of the converged energy")
        except Exception:
            import traceback
            checks.fail(traceback.format_exc())
        checks.finish()
    proxy.GetClientSideObject().AddObserver("EndEvent", continued)


class Checks:
    """A GUI test's checks: each one logged to OUTPUT.log (the GUI's own output does not reach
    the console), the failures written to OUTPUT.result by finish, which ends the GUI."""

    def __init__(self, output):
        self.output, self.failures = output, []
        self.log = open(output + ".log", "w")

    def say(self, text):
        print(text, file=self.log, flush=True)

    def check(self, condition, what):
        self.say(("ok: " if condition else "FAILED: ") + what)
        if not condition:
            self.failures.append(what)

    def fail(self, what):
        self.failures.append(what)
        self.say(what)

    def finish(self):
        with open(self.output + ".result", "w") as result:
            result.write("\n".join(self.failures) if self.failures else "passed")
        os._exit(1 if self.failures else 0)


def still_render_seconds(view):
    """The median of ten still renders of the unchanged scene (the drag benchmarks' unit)."""
    stills = []
    for _ in range(10):
        before = time.perf_counter()
        view.StillRender()
        stills.append(time.perf_counter() - before)
    return sorted(stills)[len(stills) // 2]


def timed_drag(view, at, frames, apply_move, apply_release, update):
    """A drag benchmark's drag: from display point `at`, 2 pixels up a frame, with Auto Apply
    on. Each frame sends the move, calls apply_move() (which returns the seconds it spent in
    pipeline updates) and renders; the release sends its event, calls apply_release(), then
    update(), and renders. Returns each frame's seconds, the updates' seconds among them, and
    the release's CLOCK_MONOTONIC times by step (with the first frame's window), for figures()
    and to cut a `perf record -k mono`."""
    import paraview.simple as simple
    events = ViewEvents(view)
    x, y = at
    simple.GetSettingsProxy("GeneralSettings").AutoApply = 1
    events.send("MouseMoveEvent", (x, y))
    events.send("LeftButtonPressEvent", (x, y))
    times, updating, release = [], 0.0, {}
    first = time.monotonic()
    for frame in range(1, frames + 1):
        start = time.perf_counter()
        events.send("MouseMoveEvent", (x, y + 2 * frame))
        updating += apply_move()
        simple.Render(view)
        times.append(time.perf_counter() - start)
        if frame == 1:
            release["first_frame_window"] = [first, time.monotonic()]
    release["start"] = time.monotonic()
    events.send("LeftButtonReleaseEvent", (x, y + 2 * frames))
    apply_release()
    release["event"] = time.monotonic()
    update()
    release["update"] = time.monotonic()
    simple.Render(view)
    release["render"] = time.monotonic()
    return times, updating, release


def figures(times, update, release, frames, still):
    """One drag's figures for the drag benchmarks: its first frame, the median of the others,
    the release; `release` holds CLOCK_MONOTONIC times of its steps."""
    frame = sorted(times[1:] or times)[len(times[1:] or times) // 2]
    return {"first_frame_ms": round(1000.0 * times[0], 1),
            "frame_ms": round(1000.0 * frame, 2),
            "frame_over_still": round(frame / still, 2),
            "first_frame_over_still": round(times[0] / still, 2),
            "filter_ms": round(1000.0 * update / frames, 2),
            "release_ms": round(1000.0 * (release["render"] - release["start"]), 1),
            "release_over_still": round((release["render"] - release["start"]) / still, 2),
            "release_steps_ms": {step: round(1000.0 * (release[step] - release[last]), 1)
                                 for last, step in (("start", "event"), ("event", "update"),
                                                    ("update", "render"))},
            "release_window": [release["start"], release["render"]],
            "first_frame_window": release["first_frame_window"]}


def run_benchmark(main):
    """Runs a GUI benchmark's main(out), out being LAPLACIAN_BENCH_OUTPUT or standard output, and
    ends the GUI: status 0, or 1 with the traceback printed to out; where main returns True, its
    callbacks in the event loop end it instead."""
    import sys
    import traceback
    out = open(os.environ["LAPLACIAN_BENCH_OUTPUT"], "w") if "LAPLACIAN_BENCH_OUTPUT" in os.environ else sys.stdout
    status = 1
    try:
        if main(out):
            return
        status = 0
    except Exception:
        print(traceback.format_exc(), file=out, flush=True)
    os._exit(status)
