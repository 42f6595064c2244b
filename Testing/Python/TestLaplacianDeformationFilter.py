"""The filter from Python: a real edit, the cache, pass-through and bad input."""
import math
import os
import sys
import unittest

from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkIntArray
from vtkmodules.vtkCommonExecutionModel import vtkPointSetAlgorithm
from vtkmodules.vtkCommonMisc import vtkErrorCode
from vtkmodules.vtkCommonTransforms import vtkTransform

import laplacianediting

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "Examples", "Python"))
from bumpy_plane import bumpy_plane  # noqa: E402  (the examples' test shape)


def plane_edit(mesh):
    deform = laplacianediting.vtkLaplacianDeformationFilter()
    deform.SetInputData(mesh)
    deform.SetHandleCenter(0.5, 0.5, 0.0)
    deform.SetHandleRadius(0.06)
    deform.SetROIRadius(0.35)
    return deform


def catch_errors(vtk_object):
    """Collects the messages of a VTK object's ErrorEvent instead of printing them."""
    messages = []

    def on_error(caller, event, message):
        messages.append(message)

    on_error.CallDataType = VTK_STRING
    vtk_object.AddObserver(vtkCommand.ErrorEvent, on_error)
    return messages


class TestLaplacianDeformationFilter(unittest.TestCase):
    def test_edit_moves_handle_and_keeps_outside(self):
        mesh = bumpy_plane(50)
        deform = plane_edit(mesh)
        lift = vtkTransform()
        deform.SetHandleTransform(lift)
        deform.Update()
        self.assertEqual(deform.GetNumberOfFactorizations(), 1)
        for step in range(1, 6):
            lift.Identity()
            lift.Translate(0.0, 0.0, 0.04 * step)
            deform.Update()
        self.assertEqual(deform.GetNumberOfFactorizations(), 1, "handle moves must not refactor")

        out = deform.GetOutput()
        roles = out.GetPointData().GetArray("EditRole")
        self.assertIsNotNone(roles)
        diagonal = mesh.GetLength()
        handles = 0
        for i in range(mesh.GetNumberOfPoints()):
            p, q = mesh.GetPoint(i), out.GetPoint(i)
            role = roles.GetValue(i)
            if role == deform.ROLE_FIXED:
                self.assertEqual(p, q)
            elif role == deform.ROLE_HANDLE:
                handles += 1
                self.assertLess(math.dist(q, (p[0], p[1], p[2] + 0.2)), 1e-3 * diagonal)
        self.assertEqual(handles, deform.GetNumberOfHandleVertices())
        self.assertGreater(deform.GetNumberOfROIVertices(), handles)

    def test_identity_reproduces_input(self):
        mesh = bumpy_plane(50)
        deform = plane_edit(mesh)
        deform.SetOperatorOrder(2)
        deform.SetLaplacianWeightsToCotangent()
        deform.Update()
        out = deform.GetOutput()
        worst = max(math.dist(mesh.GetPoint(i), out.GetPoint(i)) for i in range(mesh.GetNumberOfPoints()))
        self.assertLess(worst, 1e-9 * mesh.GetLength())

    def test_array_selection(self):
        mesh = bumpy_plane(30)
        labels = vtkIntArray()
        labels.SetName("Selection")
        for i in range(mesh.GetNumberOfPoints()):
            x, y, _ = mesh.GetPoint(i)
            inside = 0.2 < x < 0.8 and 0.2 < y < 0.8
            labels.InsertNextValue(2 if math.hypot(x - 0.5, y - 0.5) < 0.05 else int(inside))
        mesh.GetPointData().AddArray(labels)
        deform = laplacianediting.vtkLaplacianDeformationFilter()
        deform.SetInputData(mesh)
        deform.SetSelectionModeToArray()
        deform.SetInputArrayToProcess(0, 0, 0, 0, "Selection")  # 0: point data
        lift = vtkTransform()
        lift.Translate(0, 0, 0.1)
        deform.SetHandleTransform(lift)
        deform.Update()
        out = deform.GetOutput()
        for i in range(mesh.GetNumberOfPoints()):
            if labels.GetValue(i) == 2:
                self.assertAlmostEqual(out.GetPoint(i)[2] - mesh.GetPoint(i)[2], 0.1, delta=1e-3)
        self.assertIsNotNone(out.GetPointData().GetArray("Selection"))

    def test_bad_input_reports_error_and_passes_input_through(self):
        cases = {
            "radius": (lambda d, m: d.SetHandleRadius(-1.0), "must be positive"),
            "outside": (lambda d, m: (d.SetHandleRadius(0.5), d.SetROIRadius(0.3)), "outside the region"),
            "nan": (lambda d, m: m.GetPoints().SetPoint(3, float("nan"), 0, 0), "NaN or infinite"),
            "array": (lambda d, m: (d.SetSelectionModeToArray(),
                                    d.SetInputArrayToProcess(0, 0, 0, 0, "Missing")), "no such point array"),
        }
        for name, (spoil, expected) in cases.items():
            with self.subTest(name):
                mesh = bumpy_plane(20)
                deform = plane_edit(mesh)
                spoil(deform, mesh)
                errors = catch_errors(deform)
                deform.Update()
                self.assertTrue(any(expected in m for m in errors), errors)
                self.assertEqual(deform.GetErrorCode(), vtkErrorCode.UserError)
                out = deform.GetOutput()
                self.assertEqual(out.GetNumberOfPoints(), mesh.GetNumberOfPoints())
                self.assertEqual(out.GetNumberOfCells(), mesh.GetNumberOfCells())

    def test_every_setter_documents_itself(self):
        """help() on each public setter of each edit filter says more than its signature."""
        undocumented = []
        for filter_class in (laplacianediting.vtkLaplacianDeformationFilter,
                             laplacianediting.vtkLaplacianLandmarkWarp,
                             laplacianediting.vtkLaplacianSurfaceRegistration):
            own = [name for name in dir(filter_class) if name.startswith("Set")
                   and name not in dir(vtkPointSetAlgorithm)]
            self.assertGreater(len(own), 40, filter_class.__name__)
            for name in own:
                text = getattr(filter_class, name).__doc__ or ""
                # The wrapper writes signature lines ("Name(self...) -> ..." and "C++: ..."),
                # then the header's comment.
                prose = [line for line in text.splitlines() if line.strip() and not line.startswith(
                    (name + "(", "C++:", "    ")) and "->" not in line]
                if not prose:
                    undocumented.append(filter_class.__name__ + "." + name)
        self.assertEqual(undocumented, [])


if __name__ == "__main__":
    unittest.main()
