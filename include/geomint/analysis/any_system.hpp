#pragma once
/// Analysis of any system: order studies, symplecticity defects and a high-accuracy reference
/// flow straight from an integrator, with no hand-written adapter.
///
///   geomint::integrator<geomint::lpf<4, geomint::gauss_interior>, my_system, double> I(my_system{});
///   auto orders = geomint::analysis::study_order(I, q0, qdot0, 1.0, {8, 16, 32, 64});
///   double defect = geomint::analysis::symplecticity_defect(I, q0, qdot0, 0.25);
///
/// The reference flow (`galerkin_reference`) is the library's Galerkin variational integrator
/// of degree 8 (order 16, Gauss-Legendre quadrature) in more digits than the scalar under
/// study (50 for double, 100 for 50-digit types), with the step halved until two successive
/// refinements agree to the working precision: the answer is checked, not assumed.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "geomint/analysis/order_study.hpp"
#include "geomint/analysis/symplecticity.hpp"
#include "geomint/core/checked_cast.hpp"
#include "geomint/core/multiprecision.hpp"
#include "geomint/integrator.hpp"
#include "geomint/stepper.hpp"

namespace geomint::analysis {

/// The scalar of the reference flow for a scalar T: about twice its digits.
template <class T>
using reference_scalar_for = std::conditional_t<(std::numeric_limits<T>::digits10 <= 20), boost::multiprecision::cpp_bin_float_50,
                                                boost::multiprecision::cpp_bin_float_100>;

namespace detail {
template <class To, class From, int n>
vec<To, n> convert(const vec<From, n>& x) {
  vec<To, n> out;
  for (int i = 0; i < n; ++i) out[i] = static_cast<To>(x[i]);
  return out;
}
template <class To, class From>
dynamic_vector<To> convert_dynamic(const dynamic_vector<From>& x) {
  dynamic_vector<To> out(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) out[i] = static_cast<To>(x[i]);
  return out;
}
}  // namespace detail

/// The exact flow of Sys from (q0, p0) to time t, to the working precision of T (see above).
/// Throws std::runtime_error if 2^20 steps per unit time do not reach agreement,
/// std::domain_error for t < 0 or not finite and std::out_of_range when t is so large that the
/// step counts would overflow (t above about 1.1e12); t = 0 gives (q0, p0).
template <class Sys, class T, class R = reference_scalar_for<T>>
reference_function<T> galerkin_reference(const Sys& sys, const vec<T, Sys::dof>& q0, const vec<T, Sys::dof>& p0) {
  constexpr int n = Sys::dof;
  return [sys, q0, p0](const T& t, dynamic_vector<T>& q, dynamic_vector<T>& p) {
    using std::abs;
    using std::ceil;
    using std::max;
    using Ref = integrator<galerkin_vi<8>, Sys, R>;
    const vec<R, n> qr0 = detail::convert<R>(q0), pr0 = detail::convert<R>(p0);
    const R tr = static_cast<R>(t);
    const T tolerance = T(16) * std::numeric_limits<T>::epsilon();
    auto run = [&](long steps, vec<R, n>& qe, vec<R, n>& pe) {
      Ref I(sys, tr / R(steps));
      typename Ref::state s;
      s.q = qr0;
      s.p = pr0;
      I.advance(s, steps);
      qe = s.q;
      pe = s.p;
    };
    if (!is_finite(t) || t < T(0)) throw std::domain_error("geomint::galerkin_reference: t must be finite and >= 0");
    if (t == T(0)) {
      q = q0;
      p = p0;
      return;
    }
    // Start near 8 steps per unit time (at least 2 steps), refine until two runs agree; the
    // last refinement's 2^20 times as many steps must be a long (checked_cast.hpp).
    const auto start = checked_integer<long>(T(max(T(2), T(ceil(T(8) * abs(t))))));
    if (!start || !checked_mul(*start, 1L << 20))
      throw std::out_of_range("geomint::galerkin_reference: t = " + geomint::detail::short_number(static_cast<double>(t)) +
                              " needs more steps than a long counts (8 per unit time, refined 2^20 times)");
    long steps = *start;
    vec<R, n> qa, pa, qb, pb;
    run(steps, qa, pa);
    for (int refinement = 0; refinement < 20; ++refinement) {
      steps *= 2;
      run(steps, qb, pb);
      const R change = max(R((qb - qa).template lpNorm<Eigen::Infinity>()), R((pb - pa).template lpNorm<Eigen::Infinity>()));
      const R scale = max(R(1), R(max(R(qb.template lpNorm<Eigen::Infinity>()), R(pb.template lpNorm<Eigen::Infinity>()))));
      if (change <= static_cast<R>(tolerance) * scale) {
        q = detail::convert<T>(qb);
        p = detail::convert<T>(pb);
        return;
      }
      qa = qb;
      pa = pb;
    }
    throw std::runtime_error("geomint::galerkin_reference: no agreement after 20 refinements");
  };
}

/// Observed local and global orders of an integrator on its own system from (q0, qdot0) up to
/// t_end, against galerkin_reference (the integrator's tau is not used).
template <class Integrator>
order_result<typename Integrator::scalar> study_order(const Integrator& I, const vec<typename Integrator::scalar, Integrator::n>& q0,
                                                      const vec<typename Integrator::scalar, Integrator::n>& qdot0,
                                                      const typename Integrator::scalar& t_end,
                                                      const std::vector<long>& step_counts) {
  using T = typename Integrator::scalar;
  const auto s0 = I.initial_state(q0, qdot0);
  const auto reference = galerkin_reference<typename Integrator::system, T>(I.system_ref(), s0.q, s0.p);
  return order_study<T>(*erase(I), reference, dynamic_vector<T>(s0.q), dynamic_vector<T>(s0.p), t_end, step_counts);
}

/// max |J^T Omega J - Omega| of one step of size tau from (q0, qdot0): zero (to the accuracy of
/// the difference Jacobian, about eps^(4/5)) for a symplectic scheme.
template <class Integrator>
typename Integrator::scalar symplecticity_defect(const Integrator& I, const vec<typename Integrator::scalar, Integrator::n>& q0,
                                                 const vec<typename Integrator::scalar, Integrator::n>& qdot0,
                                                 const typename Integrator::scalar& tau) {
  using T = typename Integrator::scalar;
  constexpr int n = Integrator::n;
  const auto s0 = I.initial_state(q0, qdot0);
  phase_vector<T> z(2 * n);
  z.head(n) = s0.q;
  z.tail(n) = s0.p;
  return symplectic_defect<T>(one_step_jacobian<T>(*erase(I), tau, z));
}

}  // namespace geomint::analysis
