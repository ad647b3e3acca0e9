#pragma once
/// `lpf_fixed_point<m>`: the name under which LPF's fixed-point form was a scheme of its own.
/// Kept for one release: it is `lpf<m, gauss_interior, lagrange, fixed_point_solver>` (the
/// fixed-point form alone, schemes/gauss_fixed_point.hpp, with its own name), and
/// `lpf<m, gauss_interior>` (schemes/lpf.hpp) now takes the same steps on every natural system
/// by default, with Newton for a step beyond the sweeps' reach. Use that.

#include <string>

#include "geomint/schemes/lpf.hpp"

namespace geomint {

/// LPF of degree m on Gauss-interior nodes for natural systems in the fixed-point form alone:
/// `integrator<lpf_fixed_point<8>, Sys, T>` (a step beyond the sweeps' reach fails).
template <int M>
struct lpf_fixed_point {
  static_assert(M >= 2, "geomint::lpf_fixed_point: m must be >= 2 (at least one interior node)");
  static_assert(M <= max_floating_m, "geomint::lpf_fixed_point: m must be <= max_floating_m (16)");
  static constexpr int m = M;
  /// The scheme it names.
  using scheme = lpf<M, gauss_interior, lagrange, fixed_point_solver>;
  static std::string name() {
    return "lpf-fixed-point(m=" + std::to_string(M) + ", gauss-interior, natural systems)";
  }

  template <class Sys, class T>
  using engine = typename scheme::template engine<Sys, T>;
};

}  // namespace geomint
