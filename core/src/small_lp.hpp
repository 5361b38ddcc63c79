// Private to core: a dense simplex for the tiny linear programs of the
// pair-mesh repair (4 unknowns, a few dozen rows), in doubles.
//
// CGAL's exact LP solver answers them too, but at about 0.2 ms each it was
// most of the repair time on the bundled models. Doubles are enough where
// the caller checks the answer with exact predicates anyway. Coefficients
// below 1e-11 are taken as zero (never pivoted on) and rounding is not
// bounded, so the caller checks the rows it gets back; after 1000 pivots
// the solver gives up, and the caller can fall back to the exact solver.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace cadmedial {

// Maximizes c . x subject to A x <= b and x >= 0 (A: rows x c.size(),
// row-major). Returns the optimal x, or nullopt when the program is
// infeasible, unbounded, or not solved with confidence. When `tight` is
// given and the solver ends on an optimal basis, it receives the c.size()
// constraints that hold with equality there (the nonbasic variables): id
// j < c.size() for x_j >= 0, c.size() + i for row i; a caller can check
// that basis exactly (lp_basis_certificate.hpp).
std::optional<std::vector<double>> maximizeSmallLp(const std::vector<double>& A, const std::vector<double>& b,
                                                   const std::vector<double>& c,
                                                   std::vector<std::size_t>* tight = nullptr);

}  // namespace cadmedial
