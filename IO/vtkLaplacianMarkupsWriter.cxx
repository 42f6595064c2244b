#include "vtkLaplacianMarkupsWriter.h"

#include "vtkAbstractArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"

#include "vtk_jsoncpp.h"

#include <fstream>
#include <memory>

vtkStandardNewMacro(vtkLaplacianMarkupsWriter);

vtkLaplacianMarkupsWriter::vtkLaplacianMarkupsWriter() = default;
vtkLaplacianMarkupsWriter::~vtkLaplacianMarkupsWriter() = default;

int vtkLaplacianMarkupsWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

void vtkLaplacianMarkupsWriter::WriteData()
{
  vtkPointSet* input = vtkPointSet::SafeDownCast(this->GetInput());
  if (!input)
  {
    vtkErrorMacro(<< "No point set to write.");
    return;
  }
  vtkAbstractArray* labels = input->GetPointData()->GetAbstractArray("Label");
  const bool lps = this->CoordinateSystem == LPS;
  Json::Value controlPoints(Json::arrayValue);
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    Json::Value point;
    point["id"] = std::to_string(i + 1);
    point["label"] = labels ? labels->GetVariantValue(i).ToString() : "F-" + std::to_string(i + 1);
    Json::Value position(Json::arrayValue);
    for (int k = 0; k < 3; ++k)
    {
      position.append(lps && k < 2 ? -p[k] : p[k]);
    }
    point["position"] = position;
    point["positionStatus"] = "defined";
    controlPoints.append(point);
  }
  Json::Value markup;
  markup["type"] = "Fiducial";
  markup["coordinateSystem"] = lps ? "LPS" : "RAS";
  markup["coordinateUnits"] = "mm";
  markup["controlPoints"] = controlPoints;
  Json::Value root;
  root["@schema"] = "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/"
                    "Markups/Resources/Schema/markups-schema-v1.0.3.json#";
  root["markups"].append(markup);

  std::ofstream file(this->FileName);
  if (this->FileName.empty() || !file)
  {
    vtkErrorMacro(<< "Cannot write the markups file \"" << this->FileName << "\".");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "    ";
  builder.settings_["precision"] = 17;
  std::unique_ptr<Json::StreamWriter> writer(builder.newStreamWriter());
  writer->write(root, &file);
  file << "\n";
  if (!file)
  {
    vtkErrorMacro(<< "Writing " << this->FileName << " failed.");
    this->SetErrorCode(vtkErrorCode::OutOfDiskSpaceError);
  }
}

void vtkLaplacianMarkupsWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "CoordinateSystem: " << (this->CoordinateSystem == LPS ? "LPS" : "RAS") << "\n";
}
