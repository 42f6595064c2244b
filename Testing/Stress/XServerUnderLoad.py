"""The X server the tests render on, under the load the test stage puts on it.

Why: a test that crashed in XSync with a null Display (VTK 9.1's interactor does not check the
display it opens) had been refused its X connection. The cause: an X server resets when its
last client leaves, and a connection that arrives during the reset is dropped without a reply;
tests that start and end three at a time meet that now and then. The stage's Xvfb therefore runs
with -noreset. These checks show it, and that the connections then hold:

    XServerUnderLoad.py keeps-state          one client leaves its mark (an atom); the next sees it
    XServerUnderLoad.py connections N M      N processes each connect and leave M times: no refusal
    XServerUnderLoad.py rendering BUILD R [--ctest CTEST] [--churn C]
                                             the rendering tests, three at a time, R rounds, with C
                                             other clients coming and going: no failure

Each prints what it measured; the exit code is 0 when nothing failed.
"""
import argparse
import ctypes
import multiprocessing
import os
import re
import subprocess
import sys
import time


def xlib():
    x11 = ctypes.cdll.LoadLibrary("libX11.so.6")
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
    x11.XSync.argtypes = [ctypes.c_void_p, ctypes.c_int]
    x11.XInternAtom.restype = ctypes.c_ulong
    x11.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
    return x11


def keeps_state():
    """An atom interned by a client that then leaves, alone, is still there for the next: a
    server that resets when its last client leaves forgets it."""
    x11 = xlib()
    name = f"LAPLACIAN_EDITING_PROBE_{os.getpid()}".encode()
    display = x11.XOpenDisplay(None)
    if not display:
        print("FAILED: no X display to probe")
        return 1
    x11.XInternAtom(display, name, 0)
    x11.XSync(display, 0)
    x11.XCloseDisplay(display)
    time.sleep(0.5)  # the server notices the departure, and would reset
    display = x11.XOpenDisplay(None)
    kept = bool(display) and x11.XInternAtom(display, name, 1) != 0
    if display:
        x11.XCloseDisplay(display)
    print("the X server kept its state after its last client left" if kept else
          "FAILED: the X server reset when its last client left: run Xvfb with -noreset (a "
          "connection made during a reset is dropped, and VTK's interactor dereferences the null "
          "display it then gets)")
    return 0 if kept else 1


def connect_and_leave(times):
    x11 = xlib()
    refused = 0
    for _ in range(times):
        display = x11.XOpenDisplay(None)
        if not display:
            refused += 1
            continue
        x11.XSync(display, 0)
        x11.XCloseDisplay(display)
    return refused


def connections(processes, times):
    with multiprocessing.Pool(processes) as pool:
        refused = sum(pool.map(connect_and_leave, [times] * processes))
    print(f"{processes * times} connections from {processes} processes, {refused} refused")
    return 0 if refused == 0 else 1


def churn(stop):
    """Connects and leaves until `stop` is set: other clients coming and going, as in a busier
    stage."""
    x11 = xlib()
    while not stop.is_set():
        display = x11.XOpenDisplay(None)
        if display:
            x11.XCloseDisplay(display)


def rendering(build, rounds, ctest, churners):
    """The widget and image tests, three at a time as the stage runs them, round after round,
    with `churners` processes connecting and leaving meanwhile."""
    stop = multiprocessing.Event()
    others = [multiprocessing.Process(target=churn, args=(stop,)) for _ in range(churners)]
    for process in others:
        process.start()
    runs = failed = crashed = 0
    for round_number in range(1, rounds + 1):
        run = subprocess.run([ctest, "-R", r"^(Widget|Image)\.", "-LE", "Stress", "-j3",
                              "--output-on-failure"], cwd=build, capture_output=True, text=True)
        runs += len(re.findall(r"Test +#\d+:", run.stdout))
        failures = re.findall(r"Test +#\d+: (\S+) .*\*\*\*(\w+)", run.stdout)
        failed += len(failures)
        crashed += sum(kind in ("Exception", "SEGFAULT") for _, kind in failures)
        for name, kind in failures:
            print(f"round {round_number}: {name} {kind}", flush=True)
    stop.set()
    for process in others:
        process.join()
    print(f"{runs} rendering test runs in {rounds} rounds, three at a time, with {churners} other "
          f"clients coming and going: {failed} failed, {crashed} crashed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    commands.add_parser("keeps-state")
    load = commands.add_parser("connections")
    load.add_argument("processes", type=int)
    load.add_argument("times", type=int)
    tests = commands.add_parser("rendering")
    tests.add_argument("build")
    tests.add_argument("rounds", type=int)
    tests.add_argument("--ctest", default="ctest")
    tests.add_argument("--churn", type=int, default=0, help="other clients coming and going")
    args = parser.parse_args()
    if args.command == "keeps-state":
        sys.exit(keeps_state())
    if args.command == "connections":
        sys.exit(connections(args.processes, args.times))
    sys.exit(rendering(args.build, args.rounds, args.ctest, args.churn))
