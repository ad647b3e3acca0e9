/// A Boost.Multiprecision scalar with geomint's headers included first and without
/// geomint/core/multiprecision.hpp: Eigen would lack the scalar's traits, so the integrator
/// stops with a message naming the include (linalg/types.hpp parses Boost.Multiprecision only
/// when it is already in use, to keep files with built-in scalars fast to compile).
#include <geomint/integrator.hpp>
#include <geomint/mechanics/systems.hpp>
#if !GEOMINT_EXPECT_FAILURE
#include <geomint/core/multiprecision.hpp>
#endif
#include <boost/multiprecision/cpp_bin_float.hpp>
using T = boost::multiprecision::cpp_bin_float_50;
// Instantiating the class runs its static_asserts; no member bodies are compiled.
static_assert(sizeof(geomint::integrator<geomint::midpoint_vi, geomint::systems::pendulum, T>) > 0);
int main() { return 0; }
