"""Both interactive editors on files they cannot read (missing, unknown or no extension, corrupt,
without polygons) and without an X display (DISPLAY unset, or naming no server): required, exit
code 1 and exactly one line on stderr that says what is wrong (and, for an unknown format,
which formats work; for a display, what to do). Neither crashes.

    TestEditorErrors.py CXX_EDITOR PYTHON_EDITOR
"""
import os
import subprocess
import sys
import tempfile
import unittest

CXX_EDITOR, PYTHON_EDITOR = sys.argv[1], sys.argv[2]


class TestEditorErrors(unittest.TestCase):
    def run_editors(self, path, expected, environment=None):
        for command in ([CXX_EDITOR], [sys.executable, PYTHON_EDITOR]):
            with self.subTest(editor=os.path.basename(command[-1]), path=os.path.basename(path)):
                run = subprocess.run(command + [path], capture_output=True, text=True, timeout=60,
                                     env=environment)
                lines = [line for line in run.stderr.splitlines() if line.strip()]
                self.assertEqual(run.returncode, 1, run.stderr)
                self.assertEqual(len(lines), 1, run.stderr)
                for words in expected:
                    self.assertIn(words, lines[0])

    def test_missing_file(self):
        self.run_editors("/nonexistent/mesh.obj", ["cannot open", "/nonexistent/mesh.obj"])

    def test_unknown_format(self):
        with tempfile.NamedTemporaryFile(suffix=".xyz") as mesh:
            self.run_editors(mesh.name, ["unknown mesh format '.xyz'", "OBJ, PLY, STL, OFF, VTP or VTK"])

    def test_no_extension(self):
        with tempfile.TemporaryDirectory(suffix=".obj") as folder:  # the folder's dot is not the file's
            mesh = os.path.join(folder, "mesh")
            open(mesh, "w").close()
            self.run_editors(mesh, ["no file extension on", "OBJ, PLY, STL, OFF, VTP or VTK"])

    def test_corrupt_files(self):
        # VTK's readers complain in many lines; the editors say it in one.
        off_with_a_missing_vertex = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"
        for suffix, text in ((".ply", "not a PLY file\n"), (".stl", "not an STL file\n"),
                             (".vtp", "<not VTK XML"), (".off", off_with_a_missing_vertex)):
            with tempfile.NamedTemporaryFile("w", suffix=suffix) as mesh:
                mesh.write(text)
                mesh.flush()
                self.run_editors(mesh.name, ["cannot read", mesh.name])

    def test_file_without_polygons(self):
        with tempfile.NamedTemporaryFile("w", suffix=".obj") as mesh:
            mesh.write("v 0 0 0\nv 1 0 0\n")
            mesh.flush()
            self.run_editors(mesh.name, ["holds no polygons"])


    def test_no_x_display(self):
        mesh = os.path.join(os.environ["LAPLACIAN_EDITING_DATA_DIR"], "spot.obj")
        unreachable = dict(os.environ, DISPLAY=":12345")  # a display no server listens on
        self.run_editors(mesh, ["Cannot open the X display ':12345'", "xvfb-run"], unreachable)
        unset = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
        self.run_editors(mesh, ["Cannot open the X display (DISPLAY is unset)"], unset)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
