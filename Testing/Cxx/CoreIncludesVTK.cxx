// Compiled with the numerical core's usage requirements only, this must fail: the core has no
// VTK include directory, so nothing in it can come to depend on VTK by accident.
#include "vtkObject.h"
