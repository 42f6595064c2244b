"""Both interactive editors on files they cannot read: required, exit code 1 and exactly one line
on stderr that says what is wrong (and, for an unknown format, which formats work).

    TestEditorErrors.py CXX_EDITOR PYTHON_EDITOR
"""
import os
import subprocess
import sys
import tempfile
import unittest

CXX_EDITOR, PYTHON_EDITOR = sys.argv[1], sys.argv[2]


class TestEditorErrors(unittest.TestCase):
    def run_editors(self, path, expected):
        for command in ([CXX_EDITOR], [sys.executable, PYTHON_EDITOR]):
            with self.subTest(editor=os.path.basename(command[-1]), path=os.path.basename(path)):
                run = subprocess.run(command + [path], capture_output=True, text=True, timeout=60)
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

    def test_file_without_polygons(self):
        with tempfile.NamedTemporaryFile("w", suffix=".obj") as mesh:
            mesh.write("v 0 0 0\nv 1 0 0\n")
            mesh.flush()
            self.run_editors(mesh.name, ["holds no polygons"])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
