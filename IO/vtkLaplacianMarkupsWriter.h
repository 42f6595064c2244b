/**
 * @class   vtkLaplacianMarkupsWriter
 * @brief   writes a point set as a 3D Slicer markups point list (.mrk.json)
 *
 * Each point of the input (a vtkPointSet, in VTK's frame, Slicer's RAS) becomes a control point
 * of one point list ("Fiducial"), labelled by the "Label" point array where there is one (a
 * vtkStringArray, as vtkLaplacianMarkupsReader makes) and "F-1", "F-2", ... otherwise. The file
 * is written in CoordinateSystem: LPS by default, as Slicer writes its own; RAS as asked. Slicer
 * and SlicerMorph open it as they open their own.
 *
 * @sa vtkLaplacianMarkupsReader
 */
#ifndef vtkLaplacianMarkupsWriter_h
#define vtkLaplacianMarkupsWriter_h

#include "vtkLaplacianEditingIOModule.h" // for export macro
#include "vtkWriter.h"

#include <string> // for std::string

class VTKLAPLACIANEDITINGIO_EXPORT vtkLaplacianMarkupsWriter : public vtkWriter
{
public:
  static vtkLaplacianMarkupsWriter* New();
  vtkTypeMacro(vtkLaplacianMarkupsWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  enum CoordinateSystems
  {
    LPS = 0,
    RAS = 1
  };
  /** The file's coordinate system (the points are converted from RAS). Default LPS. */
  vtkSetClampMacro(CoordinateSystem, int, LPS, RAS);
  vtkGetMacro(CoordinateSystem, int);
  void SetCoordinateSystemToLPS() { this->SetCoordinateSystem(LPS); }
  void SetCoordinateSystemToRAS() { this->SetCoordinateSystem(RAS); }

protected:
  vtkLaplacianMarkupsWriter();
  ~vtkLaplacianMarkupsWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  std::string FileName;
  int CoordinateSystem = LPS;

private:
  vtkLaplacianMarkupsWriter(const vtkLaplacianMarkupsWriter&) = delete;
  void operator=(const vtkLaplacianMarkupsWriter&) = delete;
};

#endif
