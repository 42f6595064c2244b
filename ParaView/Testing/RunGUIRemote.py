"""Starts a one-process pvserver and the ParaView GUI connected to it, running TestGUIRemote.py;
exits with the GUI's result.

    python3 RunGUIRemote.py PARAVIEW PVSERVER PLUGIN_DIR

The GUI runs with --dr: a user's saved settings could open a dialog that waits forever."""
import os
import subprocess
import sys

paraview, pvserver, plugin_dir = sys.argv[1:4]
port = 12111 + os.getpid() % 1000
server = subprocess.Popen([pvserver, "--force-offscreen-rendering", f"--server-port={port}"],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
try:
    for line in server.stdout:  # wait until it listens
        if "Accepting connection" in line:
            break
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "TestGUIRemote.py")
    client = subprocess.run([paraview, "--dr", f"--url=cs://localhost:{port}",
                             f"--plugin-search-paths={plugin_dir}", "--plugins=LaplacianEditing",
                             f"--script={script}"], capture_output=True, text=True, timeout=280)
finally:
    server.kill()
output = os.environ["LAPLACIAN_GUI_OUTPUT"]
log = open(output + ".log").read() if os.path.exists(output + ".log") else client.stdout + client.stderr
print(log)
result = open(output + ".result").read() if os.path.exists(output + ".result") else "no result"
if result != "passed":
    sys.exit(f"FAILED: {result}")
