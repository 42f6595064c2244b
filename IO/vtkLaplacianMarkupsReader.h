/**
 * @class   vtkLaplacianMarkupsReader
 * @brief   reads 3D Slicer's landmark files: markups JSON (.mrk.json) and the legacy .fcsv
 *
 * The output is a vtkPolyData with a point and a vertex per control point, in VTK's usual frame,
 * Slicer's RAS (right, anterior, superior): a file saved in LPS (Slicer's default since 4.11)
 * has its x and y negated. The control points' labels are the "Label" point array (a
 * vtkStringArray), so that two landmark sets can be paired by label (vtkLaplacianLandmarkWarp).
 *
 * Markups JSON: every markup of the file (point lists, curves, lines...) gives its control points
 * in order, in the markup's coordinateSystem (LPS or RAS; LPS where it is missing, as Slicer's
 * schema says). Control points without a position (positionStatus "undefined" or "missing",
 * placed later in Slicer) are skipped with a warning. FCSV: the "# CoordinateSystem" comment
 * (LPS, RAS, or the legacy 1 and 0), RAS where it is missing, as files before Slicer 4.11 were;
 * the "# columns" comment names the x, y, z and label columns.
 *
 * A file that cannot be read is an error, and the output is empty.
 *
 * @sa vtkLaplacianMarkupsWriter vtkLaplacianLandmarkWarp
 */
#ifndef vtkLaplacianMarkupsReader_h
#define vtkLaplacianMarkupsReader_h

#include "vtkLaplacianEditingIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class VTKLAPLACIANEDITINGIO_EXPORT vtkLaplacianMarkupsReader : public vtkPolyDataAlgorithm
{
public:
  static vtkLaplacianMarkupsReader* New();
  vtkTypeMacro(vtkLaplacianMarkupsReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The file: .mrk.json (or any .json) or .fcsv. */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  /** Whether the file looks like a markups file, by its name (ParaView's reader factory). */
  static int CanReadFile(const char* fileName);

protected:
  vtkLaplacianMarkupsReader();
  ~vtkLaplacianMarkupsReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;

private:
  vtkLaplacianMarkupsReader(const vtkLaplacianMarkupsReader&) = delete;
  void operator=(const vtkLaplacianMarkupsReader&) = delete;
};

#endif
