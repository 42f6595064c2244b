"""The README's Python quick start, run as written on every OBJ and PLY mesh in the data folder:
required, exit code 0, no warning or error, and a region of more than ten vertices edited."""
import glob
import os
import re
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
README = os.path.join(HERE, "..", "..", "README.md")
DATA = os.environ["LAPLACIAN_EDITING_DATA_DIR"]


def quick_start_code():
    with open(README, encoding="utf-8") as readme:
        text = readme.read()
    match = re.search(r"<!-- quick-start[^>]*-->\s*```python\n(.*?)```", text, re.S)
    if not match:
        raise AssertionError("README.md has no quick-start block")
    return match.group(1)


class TestReadmeQuickStart(unittest.TestCase):
    def test_runs_on_every_mesh(self):
        meshes = sorted(glob.glob(os.path.join(DATA, "*.obj")) + glob.glob(os.path.join(DATA, "*.ply")))
        self.assertGreater(len(meshes), 5)
        with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as script:
            script.write(quick_start_code())
        try:
            for mesh in meshes:
                with self.subTest(os.path.basename(mesh)):
                    run = subprocess.run([sys.executable, script.name, mesh], capture_output=True,
                                         text=True, timeout=300)
                    log = run.stdout + run.stderr
                    self.assertEqual(run.returncode, 0, log)
                    self.assertNotRegex(log, r"WARN\||ERR\|", log)
                    edited = re.search(r"(\d+) vertices edited", run.stdout)
                    self.assertIsNotNone(edited, log)
                    self.assertGreater(int(edited.group(1)), 10, log)
                    print(os.path.basename(mesh), edited.group(0))
        finally:
            os.unlink(script.name)


if __name__ == "__main__":
    unittest.main()
