// A parallel loop over 0 .. n-1 that fails as the serial loop would: when
// several iterations throw (an OCCT Standard_Failure on a broken face, say),
// the exception rethrown is the one of the lowest index, whatever the
// threads' timing, so a run reports the same error on any number of cores.
#pragma once

#include <exception>
#include <vector>

#include <tbb/parallel_for.h>

namespace cadmedial {

template <typename Body>
void parallelForInOrder(int n, const Body& body) {
  std::vector<std::exception_ptr> failures(n > 0 ? n : 0);
  tbb::parallel_for(0, n, [&](int i) {
    try {
      body(i);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace cadmedial
