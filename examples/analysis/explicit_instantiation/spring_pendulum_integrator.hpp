#pragma once
/// A compile firewall: the 50-digit spring-pendulum integrator is compiled once, in
/// spring_pendulum_integrator.cpp; files that use it include only this header (no geomint, no
/// Eigen), so they compile in about a second. (`extern template class geomint::integrator<...>`
/// alone does not achieve this with GCC at -O2: the integrator's members are defined in the
/// class, hence inline, and GCC still instantiates them to inline them; measured in
/// docs/results/compile_time.md.)
#include <boost/multiprecision/cpp_bin_float.hpp>

namespace spring {
using scalar = boost::multiprecision::cpp_bin_float_50;
struct result {
  scalar r, phi;        ///< position after the run
  scalar energy_error;  ///< |H - H0|
};
/// `steps` steps of size tau of LPF m = 4 on Gauss nodes from rest at (r0, phi0).
result run(const scalar& r0, const scalar& phi0, const scalar& tau, long steps);
}  // namespace spring
