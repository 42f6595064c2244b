"""The ParaView stage's retry rule (scripts/ctest-retrying-x-failures) on a small CTest project of
its own: a test that fails once with the X connection failure is run again and passes; a test
that fails otherwise, on purpose, fails the run at once and is never run again.

    TestRetryRule.py RETRY_SCRIPT CMAKE
"""
import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

RETRY_SCRIPT, CMAKE = sys.argv[1], sys.argv[2]

# Each test appends a line to its own file per run, so that the runs can be counted.
PROJECT = textwrap.dedent("""\
    cmake_minimum_required(VERSION 3.16)
    project(RetryRule NONE)
    enable_testing()
    set(python "{python}")
    add_test(NAME XConnectionFailsOnce COMMAND "${{python}}" -c "
    import os, sys
    runs = open('xfails.runs', 'a+'); runs.write('run\\\\n'); runs.seek(0)
    if len(runs.readlines()) == 1:
        print('ERR| vtkXOpenGLRenderWindow: bad X server connection. DISPLAY=:99. Aborting.')
        sys.exit(134)
    print('rendered')")
    if ({ordinary})
      add_test(NAME FailsOnPurpose COMMAND "${{python}}" -c "
    import sys
    open('ordinary.runs', 'a').write('run\\\\n')
    print('an ordinary failure')
    sys.exit(1)")
    endif ()
    """)


class RetryRule(unittest.TestCase):
    def run_project(self, ordinary):
        folder = tempfile.mkdtemp()
        with open(os.path.join(folder, "CMakeLists.txt"), "w") as project:
            project.write(PROJECT.format(python=sys.executable, ordinary="ON" if ordinary else "OFF"))
        build = os.path.join(folder, "build")
        subprocess.run([CMAKE, "-S", folder, "-B", build], check=True, capture_output=True)
        run = subprocess.run([sys.executable, RETRY_SCRIPT, build], capture_output=True, text=True)
        def runs(name):
            path = os.path.join(build, name)
            return len(open(path).readlines()) if os.path.exists(path) else 0
        return run, runs("xfails.runs"), runs("ordinary.runs")

    def test_an_x_connection_failure_runs_again(self):
        run, x_runs, _ = self.run_project(ordinary=False)
        self.assertEqual(run.returncode, 0, run.stdout)
        self.assertEqual(x_runs, 2)
        self.assertIn("rerun 1 of 2: XConnectionFailsOnce", run.stdout)

    def test_an_ordinary_failure_is_never_run_again(self):
        run, x_runs, ordinary_runs = self.run_project(ordinary=True)
        self.assertEqual(run.returncode, 1, run.stdout)
        self.assertEqual(ordinary_runs, 1)
        self.assertEqual(x_runs, 1, "no rerun of anything once an ordinary failure is among them")
        self.assertIn("FailsOnPurpose (not an X connection failure: no rerun)", run.stdout)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
