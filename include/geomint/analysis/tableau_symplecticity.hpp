#pragma once
/// Exact symplecticity of a tableau of any kind (methods/tableau.hpp) from its coefficients:
/// the algebraic conditions on its irreducible method (methods/reduction.hpp), with their
/// defects.
///
/// - rk: M_ij = b_i a_ij + b_j a_ji - b_i b_j = 0 (Hairer, Lubich & Wanner, Geometric Numerical
///   Integration, 2nd ed. 2006 (HLW), Theorem VI.4.3; Lasagni, Sanz-Serna, Suris 1988);
/// - prk: b_i ahat_ij + bhat_j a_ji - b_i bhat_j = 0 and b_i = bhat_i (HLW Theorem VI.4.6; the
///   first alone suffices for separable H, which `separable` reports);
/// - rkn, and nystrom on q'' = f(q) (where Ap does not enter): bbar_i = b_i (1 - c_i) and
///   b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji) (Suris 1989; HLW Theorem VI.4.10).
/// The conditions are sufficient; for irreducible methods they are also necessary (HLW section
/// VI.7, symplectic B-series; P. Gortz & R. Scherer, Reducibility and characterization of
/// symplectic Runge-Kutta methods, ETNA 2 (1994) 194-204), hence the reduction first: Lobatto
/// IIIB with s = 2 fails them as printed and is the implicit midpoint rule.
/// tests/analysis/test_tableau_symplecticity.cpp checks the verdicts against the tree conditions
/// of the modified field (bseries/symplectic_conditions.hpp), an independent route.

#include <cstddef>
#include <string>
#include <vector>

#include "geomint/methods/reduction.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::analysis {

/// The conditions' verdict and defects on the irreducible method.
template <class K>
struct tableau_symplecticity {
  bool symplectic = false;
  bool separable = false;        ///< prk: symplectic for separable H (the matrix condition holds)
  int irreducible_stages = 0;    ///< stages of the irreducible method the conditions are on
  std::string matrix_condition;  ///< e.g. "b_i a_ij + b_j a_ji = b_i b_j"
  std::string weight_condition;  ///< prk "b_i = bhat_i", rkn "bbar_i = b_i (1 - c_i)", rk empty
  /// rk: b_i a_ij + b_j a_ji - b_i b_j; prk: b_i ahat_ij + bhat_j a_ji - b_i bhat_j;
  /// rkn: b_i (bbar_j - a_ij) - b_j (bbar_i - a_ji); over the irreducible method's stages.
  std::vector<std::vector<K>> defect;
  std::vector<K> weight_defect;  ///< prk: b_i - bhat_i; rkn: bbar_i - b_i (1 - c_i); rk: empty
  /// The first nonzero entry (row-major, 0-based), -1 when none.
  int defect_i = -1, defect_j = -1, weight_defect_i = -1;
};

/// The symplecticity conditions of `t` on its irreducible method (see the top of the file);
/// needs an exact K.
template <class K>
tableau_symplecticity<K> symplecticity_conditions(const methods::tableau_data<K>& t) {
  using methods::method_kind;
  methods::tableau_data<K> on_f = t;
  if (t.kind == method_kind::nystrom) {  // on q'' = f(q) Ap does not enter: reduce the rkn method
    on_f.kind = method_kind::rkn;
    on_f.ap.clear();
  }
  const methods::tableau_data<K> m = methods::irreducible_form(on_f).method;
  const auto s = static_cast<std::size_t>(m.stages);
  tableau_symplecticity<K> r;
  r.irreducible_stages = m.stages;
  r.defect.assign(s, std::vector<K>(s, K(0)));
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      switch (m.kind) {
        case method_kind::rk: r.defect[i][j] = m.b[i] * m.a[i][j] + m.b[j] * m.a[j][i] - m.b[i] * m.b[j]; break;
        case method_kind::prk: r.defect[i][j] = m.b[i] * m.ahat[i][j] + m.bhat[j] * m.a[j][i] - m.b[i] * m.bhat[j]; break;
        default: r.defect[i][j] = m.b[i] * (m.bbar[j] - m.a[i][j]) - m.b[j] * (m.bbar[i] - m.a[j][i]); break;
      }
      if (r.defect_i < 0 && !(r.defect[i][j] == K(0))) {
        r.defect_i = static_cast<int>(i);
        r.defect_j = static_cast<int>(j);
      }
    }
  if (m.kind == method_kind::prk || m.kind == method_kind::rkn) {
    r.weight_defect.assign(s, K(0));
    for (std::size_t i = 0; i < s; ++i) {
      r.weight_defect[i] = m.kind == method_kind::prk ? m.b[i] - m.bhat[i] : m.bbar[i] - m.b[i] * (K(1) - m.c[i]);
      if (r.weight_defect_i < 0 && !(r.weight_defect[i] == K(0))) r.weight_defect_i = static_cast<int>(i);
    }
  }
  switch (m.kind) {
    case method_kind::rk: r.matrix_condition = "b_i a_ij + b_j a_ji = b_i b_j"; break;
    case method_kind::prk:
      r.matrix_condition = "b_i ahat_ij + bhat_j a_ji = b_i bhat_j";
      r.weight_condition = "b_i = bhat_i";
      break;
    default:
      r.matrix_condition = "b_i (bbar_j - a_ij) = b_j (bbar_i - a_ji)";
      r.weight_condition = "bbar_i = b_i (1 - c_i)";
      break;
  }
  r.separable = m.kind == method_kind::prk && r.defect_i < 0;
  r.symplectic = r.defect_i < 0 && r.weight_defect_i < 0;
  return r;
}

}  // namespace geomint::analysis
