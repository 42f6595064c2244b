// The X display a render window draws on, opened and checked before VTK can use it.
//
// VTK 9.1's X interactor opens a display of its own when its window has none, and uses it
// unchecked: without a reachable X server (DISPLAY unset, or naming no server) a program that
// starts an interactor dies with a segmentation fault, and an offscreen window aborts. A window
// given an open display draws on it, and its interactor uses it too. The display is opened once
// per process and shared by its windows; it stays open until the process ends, after every
// window that draws on it.
#ifndef LaplacianEditing_Testing_XDisplay_h
#define LaplacianEditing_Testing_XDisplay_h

#include "vtkRenderWindow.h"

#include <cstdlib>
#include <iostream>
#include <string>

// Xlib's entry point alone: its header defines macros (None, Status, Bool) that collide with
// ordinary names.
extern "C" struct _XDisplay* XOpenDisplay(const char* name);

namespace XDisplay
{
/// Gives `window` the process's X display; false, with `error` saying what to do, where there
/// is none. A window of another platform than X is left as it is.
inline bool Attach(vtkRenderWindow* window, std::string& error)
{
  if (!window->IsA("vtkXOpenGLRenderWindow"))
  {
    return true;
  }
  static _XDisplay* display = XOpenDisplay(nullptr);
  if (!display)
  {
    const char* name = std::getenv("DISPLAY");
    error = std::string("Cannot open the X display ") +
      (name ? std::string("'") + name + "': no X server answers there" : "(DISPLAY is unset)") +
      ". Rendering needs one: run on a desktop, through ssh -X, or under xvfb-run -a.";
    return false;
  }
  window->SetDisplayId(static_cast<void*>(display));
  return true;
}

/// Attach, or the error on standard error and exit code 1.
inline void AttachOrExit(vtkRenderWindow* window)
{
  std::string error;
  if (!Attach(window, error))
  {
    std::cerr << error << "\n";
    std::exit(EXIT_FAILURE);
  }
}
}

#endif
