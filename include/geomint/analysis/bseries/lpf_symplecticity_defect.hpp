#pragma once
/// The leading order in tau of LPF's symplecticity defect J^T Omega J - Omega on a Lagrangian
/// L(q, qdot), per node family and m (the derivation: docs/results/schemes.md, "Classes of
/// Lagrangians").
///
/// LPF (schemes/lpf.hpp) is the Nystrom collocation method for q'' = F(q, q') on its m - 1
/// interior nodes, composed with the Legendre map p = L_v(q, v) at both ends. With the action
/// A = int_0^tau L(x, x') dt along its path x (degree m) and E = d/dt L_v - L_q (zero at the
/// nodes), integration by parts gives p1 dq1 - p0 dq0 = dA + sigma, sigma = int_0^tau E . dx dt,
/// so the step is symplectic iff d sigma = 0 (Marsden & West, Discrete mechanics and variational
/// integrators, Acta Numerica 10 (2001) 357-514: a map with p1 dq1 - p0 dq0 exact has a
/// generating function; Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd ed. 2006,
/// sections VI.5-VI.6). At t = tau theta, E . dx is a series in tau whose tau^j coefficient is a
/// polynomial in theta of degree <= j divisible by the node polynomial omega (degree m - 1), and
/// omega is orthogonal on [0, 1] to the polynomials of degree < p - (m - 1), p the order of the
/// interpolatory quadrature on the nodes (the argument of collocation's superconvergence, HLW
/// section II.1.3): sigma = O(tau^(p+1)), and so the defect -d sigma = O(tau^(p+1)). It vanishes identically where the Nystrom map is a
/// symplectic RKN method in canonical variables: a natural system (constant mass matrix, F = F(q);
/// up to a closed gauge term A(q) . qdot) and a tableau satisfying Suris' conditions
/// (scheme_structure.hpp); otherwise the tau^(p+1) coefficient is not zero (computed exactly for
/// a position-dependent mass and a constant gyroscopic term: scripts/lpf_defect_series.py).
#include <optional>
#include <string_view>

#include "geomint/analysis/order_conditions.hpp"
#include "geomint/analysis/rkn_tableau.hpp"
#include "geomint/analysis/scheme_structure.hpp"
#include "geomint/core/dispatch.hpp"

namespace geomint::analysis {

/// The Lagrangians the prediction distinguishes: natural (L = 1/2 qdot^T M qdot - V(q), M
/// constant) and every other regular Lagrangian.
enum class lagrangian_class { natural, general };

/// The order r of the leading term of LPF(m, Family)'s symplecticity defect, J^T Omega J - Omega
/// = C tau^r + O(tau^(r+1)): the quadrature order of the interior nodes plus one; std::nullopt
/// where the defect vanishes identically (natural systems and a tableau symplectic by Suris'
/// conditions). For a general Lagrangian r is the order of the bound, attained unless C happens
/// to vanish (docs/results/schemes.md).
template <int M, class Family>
std::optional<int> lpf_defect_order(lagrangian_class lagrangian) {
  const exact_rkn_tableau t = lpf_tableau<M, Family>();
  if (lagrangian == lagrangian_class::natural && symplecticity(t).symplectic) return std::nullopt;
  return quadrature_order(t) + 1;
}

/// The same for a run-time family name and m in 2..max_exact_m (std::invalid_argument otherwise).
inline std::optional<int> lpf_defect_order(std::string_view family, int m, lagrangian_class lagrangian) {
  return with_node_family(family, [&]<class Family>() {
    return with_int<2, max_exact_m>(m, [&]<int M>() { return lpf_defect_order<M, Family>(lagrangian); });
  });
}

}  // namespace geomint::analysis
