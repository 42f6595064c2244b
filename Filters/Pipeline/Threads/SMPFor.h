// SMPFor: the core's loops (ParallelFor) on VTK's SMP backend.
#ifndef LaplacianEditing_Pipeline_SMPFor_h
#define LaplacianEditing_Pipeline_SMPFor_h

#include "ParallelFor.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

namespace LaplacianEditing
{
namespace Pipeline
{
/// Runs on vtkSMPTools where its backend keeps threads (TBB, OpenMP, STDThread from VTK 9.3).
/// ParaView's VTK runs vtkSMPTools on one thread unless told otherwise
/// (VTK_SMP_BACKEND_IN_USE), and its STDThread backend starts threads at every call: there the
/// loops take ThreadPool's threads, started once.
VTKLAPLACIANEDITINGFILTERS_EXPORT void SMPFor(
  int begin, int end, const std::function<void(int first, int last)>& body);
}
}

#endif
