#include "SMPFor.h"

#include "ThreadPool.h"

#include "vtkSMP.h"
#include "vtkSMPTools.h"
#include "vtkVersionMacros.h"

#include <string>

namespace LaplacianEditing
{
namespace Pipeline
{
void SMPFor(int begin, int end, const std::function<void(int first, int last)>& body)
{
  const std::string backend = vtkSMPTools::GetBackend();
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 0)
  // Before 9.3, VTK's STDThread backend starts its threads at every call.
  if (backend == "Sequential" || backend == "STDThread")
  {
    ThreadPool::Shared().For(begin, end, body);
    return;
  }
#endif
  auto run = [&] { vtkSMPTools::For(begin, end, [&](int first, int last) { body(first, last); }); };
#if VTK_SMP_ENABLE_STDTHREAD && VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  if (backend == "Sequential")
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ std::string("STDThread") }, run);
    return;
  }
#endif
  run();
}
}
}
