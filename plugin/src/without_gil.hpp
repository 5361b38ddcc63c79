// Runs C++ work with the GIL released (other Python threads and the FreeCAD
// GUI keep going); OCCT failures become std exceptions, and any exception is
// rethrown after the GIL is back, where pybind11 turns it into Python's.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

#include <pybind11/pybind11.h>

#include <Standard_Failure.hxx>

namespace cadmedial {

template <class Work>
void withoutGil(Work&& work) {
  std::exception_ptr error;
  {
    pybind11::gil_scoped_release release;
    try {
      try {
        std::forward<Work>(work)();
      } catch (const Standard_Failure& f) {
        throw std::runtime_error(std::string("OpenCASCADE failure: ") + f.GetMessageString());
      }
    } catch (...) {
      error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace cadmedial
