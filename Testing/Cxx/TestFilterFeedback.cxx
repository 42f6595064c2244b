// What a user sees when something is off: relative radii, warnings about unlikely regions, the
// error code, a failed factorization that is not retried, and the help texts' enum names.
#include "FilterTestHelpers.h"
#include "MeshReader.h"

#include "vtkErrorCode.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSignedCharArray.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <gtest/gtest.h>

#include <sstream>

namespace
{
using Filter = vtkLaplacianDeformationFilter;

vtkSmartPointer<vtkPolyData> Bunny()
{
  std::string error;
  auto mesh = MeshReader::Read(DataDir + "/stanford-bunny.obj", error);
  EXPECT_TRUE(mesh) << error;
  return mesh;
}

// The README's quick start: radii relative to the diagonal, the handle on the highest point.
vtkSmartPointer<Filter> QuickStart(vtkPolyData* mesh)
{
  vtkIdType top = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    top = mesh->GetPoint(i)[1] > mesh->GetPoint(top)[1] ? i : top;
  }
  auto filter = vtkSmartPointer<Filter>::New();
  filter->SetInputData(mesh);
  filter->SetRadiusUnitsToDiagonalFraction();
  filter->SetHandleRadius(0.03);
  filter->SetROIRadius(0.15);
  filter->SetHandleCenter(mesh->GetPoint(top));
  filter->SetHandleTranslation(0.0, 0.05 * mesh->GetLength(), 0.0);
  return filter;
}

std::vector<signed char> Roles(Filter* filter)
{
  auto* roles = vtkSignedCharArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetArray("EditRole"));
  EXPECT_NE(roles, nullptr);
  return roles ? std::vector<signed char>(roles->GetPointer(0), roles->GetPointer(0) + roles->GetNumberOfValues())
               : std::vector<signed char>();
}
}

TEST(Feedback, RelativeRadiiSelectTheSameRegionAtAnyScale)
{
  // The bunny and the bunny scaled by 1000 about a far-away point: required, the same roles
  // point by point.
  auto bunny = Bunny();
  vtkNew<vtkTransform> scale;
  scale->Translate(500.0, -20.0, 3.0);
  scale->Scale(1000.0, 1000.0, 1000.0);
  vtkNew<vtkTransformPolyDataFilter> scaled;
  scaled->SetInputData(bunny);
  scaled->SetTransform(scale);
  scaled->Update();
  auto original = QuickStart(bunny);
  auto large = QuickStart(scaled->GetOutput());
  original->Update();
  large->Update();
  EXPECT_GT(original->GetNumberOfROIVertices(), 100);
  EXPECT_EQ(original->GetNumberOfROIVertices(), large->GetNumberOfROIVertices());
  EXPECT_EQ(original->GetNumberOfHandleVertices(), large->GetNumberOfHandleVertices());
  EXPECT_TRUE(Roles(original) == Roles(large));
  // Absolute units still mean mesh units: the same region from radii times the diagonal.
  const std::vector<signed char> relative = Roles(original);
  original->SetRadiusUnitsToAbsolute();
  original->SetHandleRadius(0.03 * bunny->GetLength());
  original->SetROIRadius(0.15 * bunny->GetLength());
  original->Update();
  EXPECT_TRUE(Roles(original) == relative);
}

TEST(Feedback, TheQuickStartDrawsNoWarning)
{
  auto filter = QuickStart(Bunny());
  ErrorCatcher warnings(filter, vtkCommand::WarningEvent);
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_EQ(warnings.Messages, "");
  EXPECT_EQ(errors.Messages, "");
  EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::NoError);
}

TEST(Feedback, RolesAreTheActiveScalarsWithTheirOwnColoursUnlessTurnedOff)
{
  auto filter = QuickStart(Bunny());
  filter->Update();
  vtkPointData* pointData = filter->GetOutput()->GetPointData();
  ASSERT_NE(pointData->GetScalars(), nullptr);
  EXPECT_STREQ(pointData->GetScalars()->GetName(), "EditRole");
  auto* table = vtkLookupTable::SafeDownCast(pointData->GetScalars()->GetLookupTable());
  ASSERT_NE(table, nullptr);
  EXPECT_TRUE(table->GetIndexedLookup());
  double handle[4];
  table->GetIndexedColor(vtkLaplacianDeformationFilter::ROLE_HANDLE, handle);
  EXPECT_GT(handle[0], 0.9); // yellow, as the paper's handle
  EXPECT_GT(handle[1], 0.8);
  EXPECT_LT(handle[2], 0.2);
  const vtkIdType anchor = table->GetAnnotatedValueIndex(vtkLaplacianDeformationFilter::ROLE_ANCHOR);
  EXPECT_EQ(table->GetAnnotation(anchor), "anchor");

  // An application with its own colour maps (ParaView) turns the table off: a mapper would
  // prefer it to the application's.
  filter->RoleColorsOff();
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPointData()->GetArray("EditRole")->GetLookupTable(), nullptr);
}

TEST(Feedback, TheSameDataCopiedAnewNeitherRefactorsNorDropsCommits)
{
  // ParaView's pipeline copies the same arrays into the filter's input on every update, which
  // changes the input's MTime but not its content: moves must not refactor, commits must stay.
  auto bunny = Bunny();
  vtkNew<vtkPolyData> input;
  input->ShallowCopy(bunny);
  auto filter = QuickStart(input);
  filter->Update();
  filter->CommitEdit();
  filter->SetHandleTranslation(0.0, 0.02 * bunny->GetLength(), 0.0);
  filter->Update();
  const int factorizations = filter->GetNumberOfFactorizations();
  input->ShallowCopy(bunny);
  filter->SetHandleTranslation(0.0, 0.03 * bunny->GetLength(), 0.0);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizations(), factorizations);
  EXPECT_EQ(filter->GetNumberOfCommits(), 1);

  // New points are a new input: the commits go, the system is factored anew.
  vtkNew<vtkPoints> points;
  points->DeepCopy(bunny->GetPoints());
  input->SetPoints(points);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfCommits(), 0);
  EXPECT_EQ(filter->GetNumberOfFactorizations(), factorizations + 1);
}

namespace
{
struct UnlikelyRegion
{
  const char* Name;
  std::function<void(vtkPolyData*, Filter*)> Set;
  const char* Warning;
};

void PrintTo(const UnlikelyRegion& c, std::ostream* os)
{
  *os << c.Name;
}

class FeedbackWarning : public ::testing::TestWithParam<UnlikelyRegion>
{
};
}

TEST_P(FeedbackWarning, FiresOnceOnItsCase)
{
  // Required: the warning on its case, once per region (not again on a handle move), and the
  // edit still made.
  const UnlikelyRegion& c = GetParam();
  auto mesh = Bunny();
  auto filter = QuickStart(mesh);
  c.Set(mesh, filter);
  ErrorCatcher warnings(filter, vtkCommand::WarningEvent);
  filter->Update();
  EXPECT_NE(warnings.Messages.find(c.Warning), std::string::npos)
    << c.Name << ": got '" << warnings.Messages << "'";
  const std::string first = warnings.Messages;
  filter->SetHandleTranslation(0.0, 0.02 * mesh->GetLength(), 0.0);
  filter->Update();
  EXPECT_EQ(warnings.Messages, first);
  EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::NoError);
}

INSTANTIATE_TEST_SUITE_P(Cases, FeedbackWarning,
  ::testing::Values(
    UnlikelyRegion{ "ForgottenHandleCenter",
      [](vtkPolyData*, Filter* f) { f->SetHandleCenter(0.0, 0.0, 0.0); }, "from the surface" },
    UnlikelyRegion{ "HandleOfOneVertex",
      [](vtkPolyData*, Filter* f) { f->SetHandleRadius(1e-5); }, "handle holds a single vertex" },
    UnlikelyRegion{ "ROIOfOneVertex",
      [](vtkPolyData*, Filter* f) {
        f->SetHandleRadius(1e-6);
        f->SetROIRadius(1e-5);
      },
      "ROI holds a single vertex" },
    UnlikelyRegion{ "ROISwallowsTheComponent",
      [](vtkPolyData*, Filter* f) { f->SetROIRadius(5.0); }, "covers the whole connected part" },
    UnlikelyRegion{ "AbsoluteRadiiOnALargeMesh",
      [](vtkPolyData* mesh, Filter* f) {
        // The README's old snippet on a mesh 1000 times larger than the radii expect.
        f->SetRadiusUnitsToAbsolute();
        f->SetHandleRadius(0.01 * 1e-3 * mesh->GetLength());
        f->SetROIRadius(0.08 * 1e-3 * mesh->GetLength());
      },
      "single vertex" },
    UnlikelyRegion{ "SecondOrderInARAPMode",
      [](vtkPolyData*, Filter* f) {
        f->SetOperatorOrder(2);
        f->SetRotationModeToAsRigidAsPossible();
      },
      "OperatorOrder 2 has no effect" },
    UnlikelyRegion{ "SecondOrderInPerEdgeImplicitMode",
      [](vtkPolyData*, Filter* f) {
        f->SetOperatorOrder(2);
        f->SetRotationModeToImplicit();
      },
      "OperatorOrder 2 has no effect" }),
  [](const ::testing::TestParamInfo<UnlikelyRegion>& info) { return info.param.Name; });

TEST(Feedback, TheErrorCodeIsSetOnRefusalAndClearedOnTheNextGoodUpdate)
{
  auto filter = QuickStart(Bunny());
  filter->Update();
  EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::NoError);
  filter->SetHandleRadius(0.2); // the handle reaches outside the ROI: refused
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_NE(errors.Messages, "");
  EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::UserError);
  filter->SetHandleRadius(0.03);
  filter->Update();
  EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::NoError);
}

TEST(Feedback, AFailedFactorizationIsNotRetriedWhileNothingItDependsOnChanges)
{
  // A memory limit the factor cannot meet: one attempt, however many handle moves follow,
  // each reporting the same error; a new limit is tried anew.
  if (!Filter::IsCholmodAvailable())
  {
    GTEST_SKIP() << "only CHOLMOD predicts the factor's size";
  }
  auto filter = QuickStart(Bunny());
  filter->SetMaximumFactorMemory(1e-4);
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizationAttempts(), 1);
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 0);
  const std::string first = errors.Messages;
  EXPECT_NE(first.find("MB allowed"), std::string::npos) << first;
  for (double lift : { 0.01, 0.02, 0.03 })
  {
    errors.Messages.clear();
    filter->SetHandleTranslation(0.0, lift, 0.0);
    filter->Update();
    EXPECT_EQ(errors.Messages, first);
    EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::UserError);
  }
  EXPECT_EQ(filter->GetNumberOfFactorizationAttempts(), 1);
  filter->SetMaximumFactorMemory(0.0);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFactorizationAttempts(), 2);
  EXPECT_EQ(filter->GetNumberOfFactorizations(), 1);
  EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::NoError);
}

TEST(Feedback, MUMPSOutsideMPISaysWhatItNeeds)
{
  // MUMPS factors across MPI processes: the serial filter has none to offer, and says so.
  auto filter = QuickStart(Bunny());
  filter->SetSolverToMUMPS();
  ErrorCatcher errors(filter);
  filter->Update();
  EXPECT_NE(errors.Messages.find("vtkPLaplacianDeformationFilter in an MPI run"), std::string::npos)
    << errors.Messages;
  EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::UserError);
  EXPECT_EQ(filter->GetNumberOfFactorizationAttempts(), 0);
  EXPECT_FALSE(filter->GetFactoredAcrossProcesses());
  filter->SetSolverToCholmod();
  filter->Update();
  EXPECT_EQ(filter->GetErrorCode(), vtkErrorCode::NoError);
}

TEST(Feedback, TheAutomaticFactorLimitIsTheMemoryAvailable)
{
  // MaximumFactorMemory 0 is 80% of the physical memory available: a real figure, not "no
  // limit" (vtksys reports 0 MB until its memory check has run).
  vtkNew<Filter> filter;
  std::ostringstream text;
  filter->Print(text);
  const std::string printed = text.str();
  const std::size_t at = printed.find("(automatic: ");
  ASSERT_NE(at, std::string::npos) << printed;
  const double megabytes = std::stod(printed.substr(at + 12));
  EXPECT_GT(megabytes, 100.0) << printed;
  EXPECT_LT(megabytes, 1e9) << printed;
}

TEST(Feedback, PrintSelfNamesEnumsAndReportsTheLastUpdate)
{
  auto filter = QuickStart(Bunny());
  filter->SetRotationModeToAsRigidAsPossible();
  filter->Update();
  std::ostringstream text;
  filter->Print(text);
  for (const char* expected : { "RotationMode: AsRigidAsPossible", "RadiusUnits: DiagonalFraction",
         "SelectionMode: Geodesic", "LaplacianWeights: Uniform", "NumberOfHandleVertices: ",
         "SetupTime: ", "FactorMemory: ", "NumberOfFactorizations: 1 (attempted 1)" })
  {
    EXPECT_NE(text.str().find(expected), std::string::npos) << expected << "\n" << text.str();
  }
}
