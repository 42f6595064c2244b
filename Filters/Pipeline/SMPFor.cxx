#include "SMPFor.h"

#include "ThreadPool.h"

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
  const char* backend = vtkSMPTools::GetBackend();
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 0)
  // Before 9.3, VTK's STDThread backend starts its threads at every call.
  if (std::strcmp(backend, "Sequential") == 0 || std::strcmp(backend, "STDThread") == 0)
  {
    ThreadPool::Shared().For(begin, end, body);
    return;
  }
#endif
  auto run = [&] { vtkSMPTools::For(begin, end, [&](int first, int last) { body(first, last); }); };
#if VTK_SMP_ENABLE_STDTHREAD && VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  if (std::strcmp(backend, "Sequential") == 0)
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ std::string("STDThread") }, run);
    return;
  }
#endif
  static_cast<void>(backend);
  run();
}
}
}
