"""pvbatch: the tests' scene edited with given properties, as a script edits it; writes the
output's points, one line each, so that the GUI test can compare a drag's result with it.

    pvbatch ScriptedEdit.py PLUGIN PROPERTIES_JSON OUTPUT_TXT
"""
import json
import os
import sys

from paraview.simple import LoadPlugin

LoadPlugin(sys.argv[1], remote=False)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import LaplacianDeformationScene as scene  # noqa: E402

properties = json.loads(sys.argv[2])
deform = scene.edit(properties.pop("RotationMode"))
for name, value in properties.items():
    setattr(deform, name, value)
deform.UpdatePipeline()
points = deform.GetClientSideObject().GetOutput().GetPoints()
with open(sys.argv[3], "w") as out:
    for i in range(points.GetNumberOfPoints()):
        out.write("%.17g %.17g %.17g\n" % points.GetPoint(i))
