#include "SMPFor.h"

#include "vtkSMP.h"
#include "vtkSMPTools.h"
#include "vtkVersionMacros.h"

#include <cstring>
#include <string>

namespace LaplacianEditing
{
namespace Pipeline
{
void SMPFor(int begin, int end, const std::function<void(int first, int last)>& body)
{
  auto run = [&] { vtkSMPTools::For(begin, end, [&](int first, int last) { body(first, last); }); };
#if VTK_SMP_ENABLE_STDTHREAD && VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  if (std::strcmp(vtkSMPTools::GetBackend(), "Sequential") == 0)
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ std::string("STDThread") }, run);
    return;
  }
#endif
  run();
}
}
}
