#pragma once
/// What backward error analysis predicts for the energy along a numerical solution, from the
/// modified field alone, evaluated numerically (elementary_differentials.hpp).
///
/// HLW (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed. 2006), sections IX.1
/// and IX.3: a method of order p has the modified field
///   f~ = f + h^p f_{p+1} + h^(p+1) f_{p+2} + ...,   f_j = sum_{|t| = j} b(t)/sigma(t) F(t)
/// (modified_equation.hpp). For a symplectic method on y' = J^{-1} grad H each f_j is
/// Hamiltonian, f_j = J^{-1} grad H_j, and the numerical solution conserves
/// H~ = H + h^p H_{p+1} + h^(p+1) H_{p+2} + ... up to the truncation, so
///   H(y_n) - H(y_0) = -sum_{j=1}^{K} h^(p+j-1) (H_{p+j}(y_n) - H_{p+j}(y_0)) + O(h^(p+K)).
/// H_j itself is not needed: grad H_j . v = omega(f_j, v) (elementary_differentials.hpp,
/// symplectic_pairing), and H_j(y_{k+1}) - H_j(y_k) is the integral of that along the segment
/// from y_k to y_{k+1} (the gradient theorem: any path gives the same value for a gradient),
/// by Gauss-Legendre quadrature in T (core/quadrature.hpp), summed over the steps. The
/// quadrature's error is estimated by a second, lower rule (its difference bounds the error of
/// the lower rule, and so, pessimistically, of the higher one).
///
/// For a method that is not symplectic the energy changes along the modified flow at the rate
///   dH/dt = grad H . f~ = sum_{j=1}^{K} h^(p+j-1) grad H . f_{p+j}   (grad H . f = 0),
/// whose mean along the solution predicts the secular drift of H(y_n) - H(y_0), and whose
/// integral over [0, t_n] predicts H(y_n) - H(y_0) itself (predict_energy_change). The same holds
/// for any first integral E of y' = f (grad E . f = 0) with its gradient given, e.g. the energy
/// E(q, v) of a Lagrangian in the variables (q, v) of lagrangian_field.hpp.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/bseries/elementary_differentials.hpp"
#include "geomint/analysis/bseries/modified_equation.hpp"
#include "geomint/core/quadrature.hpp"

namespace geomint::analysis::bseries {

/// The leading terms f_{p+1}, ..., f_{p+K} of a modified field, coefficients b(t)/sigma(t) in T.
template <class T>
struct modified_terms {
  tree_set trees{1, 1};
  int order = 1;                ///< p, the method's order
  int terms = 1;                ///< K
  std::vector<bool> wanted;     ///< the trees evaluated: orders 1..p+K, and (two colours) the trees that can be nonzero
  std::vector<T> coefficient;   ///< b(t)/sigma(t), zero outside orders p+1..p+K
};

/// The terms of the modified field b (modified_field of the method's a(t)) of a method of
/// order p, on the trees marked in `wanted` (all if empty), converted to T by `convert`.
/// std::invalid_argument if p + K exceeds the trees' order or the field is not f at order <= p.
template <class T, class K, class Convert>
modified_terms<T> make_modified_terms(const tree_set& trees, const std::vector<K>& b, std::vector<bool> wanted, int order,
                                      int terms, Convert&& convert) {
  if (order < 1 || terms < 1 || order + terms > trees.max_order())
    throw std::invalid_argument("geomint::analysis::bseries::make_modified_terms: order " + std::to_string(order) + " + " +
                                std::to_string(terms) + " term(s) needs trees of order " + std::to_string(order + terms) +
                                ", the tree set has " + std::to_string(trees.max_order()));
  if (b.size() != static_cast<std::size_t>(trees.size()))
    throw std::invalid_argument("geomint::analysis::bseries::make_modified_terms: one coefficient b(t) per tree is needed");
  if (wanted.empty()) wanted.assign(static_cast<std::size_t>(trees.size()), true);
  modified_terms<T> m;
  m.trees = trees;
  m.order = order;
  m.terms = terms;
  m.coefficient.assign(b.size(), T(0));
  for (int t = 0; t < trees.size(); ++t) {
    const auto i = static_cast<std::size_t>(t);
    const int n = trees[t].order;
    if (n > order + terms) wanted[i] = false;
    if (!wanted[i]) continue;
    if (n <= order && !(b[i] == K(n == 1 ? 1 : 0)))
      throw std::invalid_argument("geomint::analysis::bseries::make_modified_terms: the modified field differs from f below order " +
                                  std::to_string(order + 1) + ": the method's order is not " + std::to_string(order));
    if (n > order) m.coefficient[i] = convert(b[i]) / T(trees[t].sigma);
  }
  m.wanted = std::move(wanted);
  return m;
}

/// f_{p+1}(y), ..., f_{p+K}(y) (index j - 1 holds f_{p+j}).
template <class T, class Field>
std::vector<vec<T, Field::dimension>> modified_field_terms(const modified_terms<T>& m, const Field& f,
                                                           const vec<T, Field::dimension>& y) {
  const auto F = elementary_differentials(m.trees, f, y, &m.wanted);
  std::vector<vec<T, Field::dimension>> out(static_cast<std::size_t>(m.terms), vec<T, Field::dimension>::Zero());
  for (int t = m.trees.first(m.order + 1); t < m.trees.first(m.order + m.terms + 1); ++t)
    if (m.wanted[static_cast<std::size_t>(t)])
      out[static_cast<std::size_t>(m.trees[t].order - m.order - 1)] +=
          m.coefficient[static_cast<std::size_t>(t)] * F[static_cast<std::size_t>(t)];
  return out;
}

/// The predicted energy error along a solution y_0, ..., y_N of a symplectic method.
template <class T>
struct energy_error_prediction {
  std::vector<T> error;       ///< -sum_j h^(p+j-1) (H_{p+j}(y_n) - H_{p+j}(y_0)), n = 0..N
  T quadrature_estimate{0};   ///< max_n of |error(rule Q) - error(lower rule)|
};

namespace detail {
/// sum_j h^(p+j-1) form(f_{p+j}(y)) for a linear form `form` on vectors.
template <class T, class Field, class Form>
T modified_form(const modified_terms<T>& m, const Field& f, const vec<T, Field::dimension>& y, const T& h, Form&& form) {
  const auto terms = modified_field_terms(m, f, y);
  T power(1);
  for (int k = 0; k < m.order; ++k) power *= h;
  T sum(0);
  for (const auto& fj : terms) {
    sum += power * form(fj);
    power *= h;
  }
  return sum;
}

/// sum_j h^(p+j-1) omega(f_{p+j}(y), v).
template <class T, class Field>
T modified_pairing(const modified_terms<T>& m, const Field& f, const vec<T, Field::dimension>& y,
                   const vec<T, Field::dimension>& v, const T& h) {
  return modified_form(m, f, y, h, [&](const vec<T, Field::dimension>& fj) { return symplectic_pairing<T, Field::dimension>(fj, v); });
}
}  // namespace detail

/// The prediction along `solution` (y_0, ..., y_N, step h) with the Q-point Gauss-Legendre rule
/// on each step's segment, checked against the rule of QLow points.
template <int Q = 8, int QLow = 6, class T, class Field>
energy_error_prediction<T> predict_energy_error(const modified_terms<T>& m, const Field& f,
                                                const std::vector<vec<T, Field::dimension>>& solution, const T& h) {
  static_assert(QLow < Q, "geomint::analysis::bseries::predict_energy_error: the check rule has fewer points");
  const auto rule = gauss_legendre_rule<Q, T>();
  const auto low = gauss_legendre_rule<QLow, T>();
  energy_error_prediction<T> out;
  out.error.assign(solution.size(), T(0));
  T sum(0), sum_low(0);
  for (std::size_t n = 1; n < solution.size(); ++n) {
    const vec<T, Field::dimension> step = solution[n] - solution[n - 1];
    for (int k = 0; k < Q; ++k)
      sum += rule.weights[static_cast<std::size_t>(k)] *
             detail::modified_pairing(m, f, vec<T, Field::dimension>(solution[n - 1] + rule.points[static_cast<std::size_t>(k)] * step), step, h);
    for (int k = 0; k < QLow; ++k)
      sum_low += low.weights[static_cast<std::size_t>(k)] *
                 detail::modified_pairing(m, f, vec<T, Field::dimension>(solution[n - 1] + low.points[static_cast<std::size_t>(k)] * step), step, h);
    out.error[n] = -sum;
    using std::abs;
    const T gap = abs(T(sum - sum_low));
    if (gap > out.quadrature_estimate) out.quadrature_estimate = gap;
  }
  return out;
}

/// The predicted change rate sum_j h^(p+j-1) grad E . f_{p+j} of a first integral E at every
/// y_n, grad E(y) given by `gradient` (for a method that is not symplectic).
template <class T, class Field, class Gradient>
std::vector<T> predict_energy_rate(const modified_terms<T>& m, const Field& f,
                                   const std::vector<vec<T, Field::dimension>>& solution, const T& h, Gradient&& gradient) {
  std::vector<T> rate;
  rate.reserve(solution.size());
  for (const auto& y : solution) {
    const vec<T, Field::dimension> g = gradient(y);
    rate.push_back(detail::modified_form(m, f, y, h, [&](const vec<T, Field::dimension>& fj) { return T(g.dot(fj)); }));
  }
  return rate;
}

/// The same for E = H of a Hamiltonian field f = J^{-1} grad H: grad H = (-f_p, f_q).
template <class T, class Field>
std::vector<T> predict_energy_rate(const modified_terms<T>& m, const Field& f,
                                   const std::vector<vec<T, Field::dimension>>& solution, const T& h) {
  constexpr int n = Field::dimension / 2;
  return predict_energy_rate(m, f, solution, h, [&](const vec<T, Field::dimension>& y) {
    const vec<T, Field::dimension> fy = f.template operator()<T>(y);
    vec<T, Field::dimension> g;
    for (int i = 0; i < n; ++i) {  // entry by entry: GCC 12 -O3 -Warray-bounds on Eigen's packets
      g[i] = -fy[n + i];
      g[n + i] = fy[i];
    }
    return g;
  });
}

/// The integrals I_n = int_0^{t_n} r(t) dt of a function sampled at t_k = k h (r_0, ..., r_N), by
/// the cubic through four neighbouring samples on every step:
///   step 0:          h/24 (9 r_0 + 19 r_1 - 5 r_2 + r_3),
///   step k (inner):  h/24 (-r_{k-1} + 13 r_k + 13 r_{k+1} - r_{k+2}),
///   step N - 1:      h/24 (r_{N-3} - 5 r_{N-2} + 19 r_{N-1} + 9 r_N)
/// (exact for cubics: error O(h^4) relative to the integral for a smooth r); with fewer than four
/// samples the trapezoidal rule (O(h^2)).
template <class T>
std::vector<T> cumulative_integral(const std::vector<T>& r, const T& h) {
  std::vector<T> out(r.size(), T(0));
  const std::size_t N = r.empty() ? 0 : r.size() - 1;
  for (std::size_t k = 0; k < N; ++k) {
    T step;
    if (N < 3) step = h * (r[k] + r[k + 1]) / T(2);
    else if (k == 0) step = h * (T(9) * r[0] + T(19) * r[1] - T(5) * r[2] + r[3]) / T(24);
    else if (k == N - 1) step = h * (r[N - 3] - T(5) * r[N - 2] + T(19) * r[N - 1] + T(9) * r[N]) / T(24);
    else step = h * (-r[k - 1] + T(13) * r[k] + T(13) * r[k + 1] - r[k + 2]) / T(24);
    out[k + 1] = out[k] + step;
  }
  return out;
}

/// The predicted E(y_n) - E(y_0) along the solution y_0, ..., y_N (step h) of a method that need
/// not be symplectic: the integral over [0, t_n] of the rate along the modified flow
/// (predict_energy_rate), evaluated at the numerical y_k (y_k is the modified flow at t_k up to
/// the truncation of the modified field) and integrated by cumulative_integral. Relative to the
/// prediction, the quadrature's error is O(h^4) and the terms after the K-th O(h^K) (a symmetric
/// method has f_{p+2} = 0, so O(h^2) at K = 1).
template <class T, class Field, class Gradient>
std::vector<T> predict_energy_change(const modified_terms<T>& m, const Field& f,
                                     const std::vector<vec<T, Field::dimension>>& solution, const T& h, Gradient&& gradient) {
  return cumulative_integral(predict_energy_rate(m, f, solution, h, std::forward<Gradient>(gradient)), h);
}

}  // namespace geomint::analysis::bseries
