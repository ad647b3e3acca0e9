#pragma once
/// The one form the integrator runs: every tableau kind, and every composition, written
/// exactly as a Nystrom method for q'' = F(q, q') with one more coefficient d,
///
///   Q_i = q + c_i h v + h^2 sum_j a_ij F_j,   V_i = v + h sum_j ap_ij F_j,   F_i = F(Q_i, V_i),
///   q1  = q + d h v + h^2 sum_j bbar_j F_j,   v1  = v + h sum_j b_j F_j,
///
/// (d = 1 for every consistent method). The conversions are exact, over the tableau's own
/// coefficients (Hairer, Norsett & Wanner, Solving ODEs I, section II.14; docs/references.md):
/// - rkn: as it is, without V_i (valid for q'' = f(q) only: natural systems);
/// - nystrom: as it is;
/// - rk on the first-order form y = (q, v), q' = v, v' = F: Q_i = q + h sum_j a_ij V_j gives
///   c_i = sum_j a_ij, A -> A A, Ap = A, bbar = b^T A, d = sum_j b_j;
/// - prk with (A, b) on q' = M^{-1} p and (Ahat, bhat) on p' = -grad V: A -> A Ahat, Ap = Ahat,
///   c_i = sum_j a_ij, bbar = b^T Ahat, b -> bhat, d = sum_j b_j (on natural systems, where
///   p = M v; there the form with v is the form with p);
/// - a composition with steps gamma_l h of a base form: the stages of all sub-steps, the base's
///   coefficients scaled by gamma_l and coupled through the sub-steps' start values.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/methods/coefficients.hpp"
#include "geomint/methods/composition.hpp"
#include "geomint/methods/tableau.hpp"

namespace geomint::methods {

template <class K>
struct nystrom_form {
  method_kind kind = method_kind::nystrom;
  std::string name;
  int stages = 0;
  std::vector<K> c, bbar, b;
  std::vector<std::vector<K>> a, ap;
  K d = K(1);
  /// False for rkn (and compositions of it): the method is defined for q'' = f(q) only.
  bool has_velocity_stages = true;
  /// rkn and prk run on natural systems only (see the top of this file).
  bool natural_only = false;
  /// A strictly lower triangular: explicit on q'' = f(q); with Ap also: explicit on F(q, q').
  bool explicit_positions = false, explicit_velocities = false;
};

namespace detail {
template <class K>
using matrix = std::vector<std::vector<K>>;

template <class K>
matrix<K> zero_matrix(int s) {
  return matrix<K>(static_cast<std::size_t>(s), std::vector<K>(static_cast<std::size_t>(s), K(0)));
}
template <class K>
matrix<K> product(const matrix<K>& x, const matrix<K>& y) {
  const std::size_t s = x.size();
  matrix<K> out = zero_matrix<K>(static_cast<int>(s));
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t k = 0; k < s; ++k)
      for (std::size_t j = 0; j < s; ++j) out[i][j] = out[i][j] + x[i][k] * y[k][j];
  return out;
}
template <class K>
std::vector<K> row_sums(const matrix<K>& x) {
  std::vector<K> out;
  for (const auto& row : x) {
    K s(0);
    for (const K& v : row) s = s + v;
    out.push_back(s);
  }
  return out;
}
template <class K>
std::vector<K> left_product(const std::vector<K>& b, const matrix<K>& x) {
  std::vector<K> out(b.size(), K(0));
  for (std::size_t i = 0; i < b.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[j] = out[j] + b[i] * x[i][j];
  return out;
}
template <class K>
K sum(const std::vector<K>& b) {
  K s(0);
  for (const K& v : b) s = s + v;
  return s;
}
template <class K>
bool lower(const matrix<K>& x) {
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i; j < x.size(); ++j)
      if (!(x[i][j] == K(0))) return false;
  return true;
}
template <class K>
void check_sizes(const tableau_data<K>& t) {
  const auto s = static_cast<std::size_t>(t.stages);
  auto vec_ok = [&](const std::vector<K>& v, const char* what) {
    if (v.size() != s) throw std::invalid_argument(std::string("tableau: ") + what + " needs " + std::to_string(s) + " entries");
  };
  auto mat_ok = [&](const matrix<K>& m, const char* what) {
    bool ok = m.size() == s;
    for (const auto& row : m) ok = ok && row.size() == s;
    if (!ok) throw std::invalid_argument(std::string("tableau: ") + what + " needs " + std::to_string(s) + " x " + std::to_string(s) + " entries");
  };
  if (t.stages < 1) throw std::invalid_argument("tableau: stages must be >= 1");
  vec_ok(t.c, "c");
  mat_ok(t.a, "a");
  vec_ok(t.b, "b");
  if (t.kind == method_kind::rkn || t.kind == method_kind::nystrom) vec_ok(t.bbar, "bbar");
  if (t.kind == method_kind::nystrom) mat_ok(t.ap, "ap");
  if (t.kind == method_kind::prk) {
    mat_ok(t.ahat, "ahat");
    vec_ok(t.bhat, "bhat");
  }
}
template <class K>
void classify(nystrom_form<K>& f) {
  f.explicit_positions = lower(f.a);
  f.explicit_velocities = f.explicit_positions && (!f.has_velocity_stages || lower(f.ap));
}
}  // namespace detail

/// The Nystrom form of a tableau of any kind (std::invalid_argument for inconsistent sizes).
template <class K>
nystrom_form<K> nystrom_form_of(const tableau_data<K>& t) {
  detail::check_sizes(t);
  nystrom_form<K> f;
  f.kind = t.kind;
  f.name = t.name;
  f.stages = t.stages;
  switch (t.kind) {
    case method_kind::rkn:
      f.c = t.c;
      f.a = t.a;
      f.ap = detail::zero_matrix<K>(t.stages);
      f.bbar = t.bbar;
      f.b = t.b;
      f.has_velocity_stages = false;
      f.natural_only = true;
      break;
    case method_kind::nystrom:
      f.c = t.c;
      f.a = t.a;
      f.ap = t.ap;
      f.bbar = t.bbar;
      f.b = t.b;
      break;
    case method_kind::rk:
    case method_kind::prk: {
      const auto& ahat = t.kind == method_kind::rk ? t.a : t.ahat;
      f.c = detail::row_sums(t.a);
      f.a = detail::product(t.a, ahat);
      f.ap = ahat;
      f.bbar = detail::left_product(t.b, ahat);
      f.b = t.kind == method_kind::rk ? t.b : t.bhat;
      f.d = detail::sum(t.b);
      f.natural_only = t.kind == method_kind::prk;
      break;
    }
  }
  detail::classify(f);
  return f;
}

/// The Nystrom form of a fixed-size tableau (rk, prk, rkn, nystrom).
template <class Tableau>
  requires requires(const Tableau& t) { data_of(t); }
nystrom_form<typename Tableau::coefficient> nystrom_form_of(const Tableau& t) {
  return nystrom_form_of(data_of(t));
}

/// The steps gamma_1 h .. gamma_k h of `base` as one form: the stages of all sub-steps, coupled
/// through the sub-steps' start values (detail::compose_coefficients, methods/composition.hpp).
template <class K>
nystrom_form<K> compose(const nystrom_form<K>& base, const std::vector<K>& gamma) {
  const int s = base.stages, k = static_cast<int>(gamma.size());
  if (k < 1) throw std::invalid_argument("composition: at least one sub-step");
  nystrom_form<K> f;
  f.kind = base.kind;
  f.name = base.name;
  f.stages = s * k;
  f.has_velocity_stages = base.has_velocity_stages;
  f.natural_only = base.natural_only;
  const auto n = static_cast<std::size_t>(f.stages);
  f.c.assign(n, K(0));
  f.bbar.assign(n, K(0));
  f.b.assign(n, K(0));
  f.a = detail::zero_matrix<K>(f.stages);
  f.ap = detail::zero_matrix<K>(f.stages);
  f.d = detail::compose_coefficients(base, base.d, gamma, f);
  detail::classify(f);
  return f;
}

/// The Nystrom form of a composition.
template <class Base, int K>
nystrom_form<typename Base::coefficient> nystrom_form_of(const composition<Base, K>& t) {
  return compose(nystrom_form_of(t.base), std::vector<typename Base::coefficient>(t.gamma.begin(), t.gamma.end()));
}

/// The form in the scalar T, every coefficient at T's full precision (coefficient_converter).
template <class T, class K>
nystrom_form<T> to_scalar(const nystrom_form<K>& f) {
  coefficient_converter<T> convert;
  auto vec = [&](const std::vector<K>& x) {
    std::vector<T> out;
    for (const K& v : x) out.push_back(convert(v));
    return out;
  };
  nystrom_form<T> out;
  out.kind = f.kind;
  out.name = f.name;
  out.stages = f.stages;
  out.c = vec(f.c);
  out.bbar = vec(f.bbar);
  out.b = vec(f.b);
  for (const auto& row : f.a) out.a.push_back(vec(row));
  for (const auto& row : f.ap) out.ap.push_back(vec(row));
  out.d = convert(f.d);
  out.has_velocity_stages = f.has_velocity_stages;
  out.natural_only = f.natural_only;
  out.explicit_positions = f.explicit_positions;
  out.explicit_velocities = f.explicit_velocities;
  return out;
}

}  // namespace geomint::methods
