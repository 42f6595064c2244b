#include "vtkLaplacianMarkupsReader.h"

#include "vtkCellArray.h"
#include "vtkErrorCode.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include "vtk_jsoncpp.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkLaplacianMarkupsReader);

namespace
{
struct ControlPoint
{
  double Position[3];
  std::string Label;
};

// RAS from a point in `system` (LPS or RAS); false for another system.
bool ToRAS(const std::string& system, double point[3])
{
  std::string upper = system;
  std::transform(upper.begin(), upper.end(), upper.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (upper == "LPS" || upper == "1")
  {
    point[0] = -point[0];
    point[1] = -point[1];
    return true;
  }
  return upper == "RAS" || upper == "0";
}

bool EndsWith(const std::string& text, const std::string& end)
{
  return text.size() >= end.size() &&
    std::equal(end.rbegin(), end.rend(), text.rbegin(), [](char a, char b) {
      return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
    });
}

// Markups JSON: every markup's control points. Returns an error, empty on success; `skipped`
// counts points without a position.
std::string ReadJSON(std::istream& file, std::vector<ControlPoint>& points, int& skipped)
{
  Json::CharReaderBuilder builder;
  Json::Value root;
  std::string errors;
  if (!Json::parseFromStream(builder, file, &root, &errors))
  {
    return "not valid JSON: " + errors;
  }
  const Json::Value& markups = root["markups"];
  if (!markups.isArray() || markups.empty())
  {
    return "no \"markups\" array: not a Slicer markups file";
  }
  for (const Json::Value& markup : markups)
  {
    const std::string system = markup.get("coordinateSystem", "LPS").asString();
    for (const Json::Value& control : markup["controlPoints"])
    {
      const Json::Value& position = control["position"];
      const std::string status = control.get("positionStatus", "defined").asString();
      if (status != "defined" || !position.isArray())
      {
        ++skipped;
        continue;
      }
      ControlPoint point;
      if (position.size() != 3 || !position[0].isNumeric() || !position[1].isNumeric() ||
        !position[2].isNumeric())
      {
        return "control point \"" + control.get("label", "").asString() +
          "\" has no three coordinates";
      }
      for (Json::ArrayIndex k = 0; k < 3; ++k)
      {
        point.Position[k] = position[k].asDouble();
      }
      if (!ToRAS(system, point.Position))
      {
        return "unknown coordinateSystem \"" + system + "\" (Slicer writes LPS or RAS)";
      }
      point.Label = control.get("label", "").asString();
      points.push_back(point);
    }
  }
  return {};
}

// The fields of one CSV line; a field in double quotes may hold commas.
std::vector<std::string> SplitCSV(const std::string& line)
{
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line)
  {
    if (c == '"')
    {
      quoted = !quoted;
    }
    else if (c == ',' && !quoted)
    {
      fields.emplace_back();
    }
    else if (c != '\r')
    {
      fields.back() += c;
    }
  }
  return fields;
}

std::string Trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\r");
  const auto last = text.find_last_not_of(" \t\r");
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

// FCSV: the comment lines say the coordinate system and the columns.
std::string ReadFCSV(std::istream& file, std::vector<ControlPoint>& points)
{
  std::string system = "RAS";
  std::map<std::string, std::size_t> columns = { { "x", 1 }, { "y", 2 }, { "z", 3 }, { "label", 11 } };
  std::string line;
  for (int number = 1; std::getline(file, line); ++number)
  {
    if (Trim(line).empty())
    {
      continue;
    }
    if (line[0] == '#')
    {
      const auto equals = line.find('=');
      const std::string key = equals == std::string::npos ? "" : Trim(line.substr(1, equals - 1));
      const std::string value = equals == std::string::npos ? "" : Trim(line.substr(equals + 1));
      if (key == "CoordinateSystem")
      {
        system = value;
      }
      else if (key == "columns")
      {
        const std::vector<std::string> names = SplitCSV(value);
        columns.clear();
        for (std::size_t k = 0; k < names.size(); ++k)
        {
          columns[Trim(names[k])] = k;
        }
      }
      continue;
    }
    const std::vector<std::string> fields = SplitCSV(line);
    ControlPoint point;
    for (int k = 0; k < 3; ++k)
    {
      const auto column = columns.find(std::string(1, "xyz"[k]));
      std::istringstream field(column == columns.end() || column->second >= fields.size()
          ? std::string()
          : fields[column->second]);
      if (!(field >> point.Position[k]))
      {
        return "line " + std::to_string(number) + " has no " + std::string(1, "xyz"[k]) +
          " coordinate";
      }
    }
    if (!ToRAS(system, point.Position))
    {
      return "unknown CoordinateSystem \"" + system + "\" (Slicer writes LPS or RAS)";
    }
    const auto label = columns.find("label");
    point.Label = label != columns.end() && label->second < fields.size() ? fields[label->second] : "";
    points.push_back(point);
  }
  return {};
}
}

vtkLaplacianMarkupsReader::vtkLaplacianMarkupsReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkLaplacianMarkupsReader::~vtkLaplacianMarkupsReader() = default;

int vtkLaplacianMarkupsReader::CanReadFile(const char* fileName)
{
  return fileName && (EndsWith(fileName, ".json") || EndsWith(fileName, ".fcsv"));
}

int vtkLaplacianMarkupsReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->SetErrorCode(vtkErrorCode::NoError);
  std::ifstream file(this->FileName);
  if (this->FileName.empty() || !file)
  {
    vtkErrorMacro(<< "Cannot open the markups file \"" << this->FileName << "\".");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return 1;
  }
  std::vector<ControlPoint> points;
  int skipped = 0;
  const std::string error = EndsWith(this->FileName, ".fcsv") ? ReadFCSV(file, points)
                                                              : ReadJSON(file, points, skipped);
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot read " << this->FileName << ": " << error << ".");
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    return 1;
  }
  if (skipped > 0)
  {
    vtkWarningMacro(<< this->FileName << ": " << skipped
                    << " control points have no position (not placed in Slicer) and were left out.");
  }
  vtkNew<vtkPoints> positions;
  positions->SetDataTypeToDouble();
  vtkNew<vtkStringArray> labels;
  labels->SetName("Label");
  vtkNew<vtkCellArray> vertices;
  for (const ControlPoint& point : points)
  {
    const vtkIdType id = positions->InsertNextPoint(point.Position);
    labels->InsertNextValue(point.Label);
    vertices->InsertNextCell(1, &id);
  }
  output->SetPoints(positions);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(labels);
  return 1;
}

void vtkLaplacianMarkupsReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
