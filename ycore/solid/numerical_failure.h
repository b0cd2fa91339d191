// A run that has gone numerically wrong (a non-finite force or position): caught by the
// driver, which writes a last frame for inspection and exits 3 (doc/architecture.md "The run").
#pragma once

#include <stdexcept>
#include <string>

#include "ycore/state/state.h"

namespace ydry {

struct NumericalFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What usually makes an explicit FDEM run fail, for the end of the messages.
inline constexpr const char* kNumericalFailureCauses =
    "the explicit step is likely too long for the stiffness (lower solver.mechanics_safety, "
    "solver.joint_penalty or contact.penalty), an element has inverted (a mesh too coarse for "
    "its strains, a material too soft for its load), or a body falls: nothing (a support, a "
    "contact, a bond) holds it against its load, gravity say";

// "node I of triangle T (material M, initially at x = X m, y = Y m)": where a failure is.
std::string describe_node(const State& state, index_t node);

// Throws NumericalFailure for a solid whose out-of-balance force has turned non-finite,
// naming the first node with a non-finite position or force (its triangle, material and
// initial position), the time and the mechanical step, and the likely causes; `what` says
// where in the solver (e.g. "relaxation step 1234").
[[noreturn]] void report_non_finite_solid(const State& state, const std::string& what);

}  // namespace ydry
