#pragma once
/// The factory behind stepper.hpp for one system and scalar; included by stepper_tu.cpp only.
#include <stdexcept>

#include "geomint/integrator.hpp"
#include "stepper.hpp"

namespace geomint::tools {
namespace detail {

using geomint::detail::all_finite;
using geomint::detail::is_finite;

/// Wraps an engine (anything with `one_step(q, p, tau, q1, p1, opt)`) of system Sys.
template <class Engine, class Sys, class T>
class engine_stepper final : public stepper<T> {
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;

 public:
  engine_stepper(const Sys& sys, Engine engine, std::string name)
      : sys_(sys), engine_(std::move(engine)), name_(std::move(name)) {}
  int dof() const override { return n; }
  std::string name() const override { return name_; }

  step_status step(const state_vector<T>& q, const state_vector<T>& p, const T& tau, state_vector<T>& q1,
                   state_vector<T>& p1, const newton_options<T>& opt) const override {
    step_status st;
    if (q.size() != n || p.size() != n) throw std::invalid_argument("state of the wrong dimension");
    if (!is_finite(tau) || !(tau > T(0))) {
      st.reason = step_failure::invalid_step_size;
      return st;
    }
    const V qf = q, pf = p;
    if (!all_finite(qf) || !all_finite(pf)) {
      st.reason = step_failure::non_finite_input;
      return st;
    }
    V q1f = V::Zero(), p1f = V::Zero();
    st = engine_.one_step(qf, pf, tau, q1f, p1f, opt);
    if (st && (!all_finite(q1f) || !all_finite(p1f))) st.reason = step_failure::non_finite_iterate;
    if (st) {
      q1 = q1f;
      p1 = p1f;
    }
    return st;
  }
  T energy(const state_vector<T>& q, const state_vector<T>& p) const override {
    V v;
    if (!geomint::detail::derivatives<Sys, T>::velocity(sys_, V(q), V(p), v)) return std::numeric_limits<T>::quiet_NaN();
    return energy_qv<Sys, T>(sys_, V(q), v);
  }
  state_vector<T> momentum(const state_vector<T>& q, const state_vector<T>& qdot) const override {
    return geomint::momentum<Sys, T>(sys_, V(q), V(qdot));
  }

 private:
  Sys sys_;
  Engine engine_;
  std::string name_;
};

template <class Engine, class Sys, class T>
std::unique_ptr<stepper<T>> wrap(const Sys& sys, Engine engine, std::string name) {
  return std::make_unique<engine_stepper<Engine, Sys, T>>(sys, std::move(engine), std::move(name));
}

template <class Scheme, class Sys, class T>
std::unique_ptr<stepper<T>> make_scheme(const Sys& sys) {
  return wrap<typename Scheme::template engine<Sys, T>, Sys, T>(sys, typename Scheme::template engine<Sys, T>(sys),
                                                                 Scheme::name());
}

/// The LPF engine of degree M on a family and basis (the step code is shared by every family:
/// the family only changes the weights).
template <int M, class Family, class Sys, class T>
std::unique_ptr<stepper<T>> make_lpf_f(const scheme_spec& s, const Sys& sys) {
  if (s.basis == "lagrange") return make_scheme<lpf<M, Family, lagrange>, Sys, T>(sys);
  if (s.basis == "bernstein") return make_scheme<lpf<M, Family, bernstein>, Sys, T>(sys);
  throw std::invalid_argument("unknown basis '" + s.basis + "' (lagrange|bernstein)");
}

template <int M, class Sys, class T>
std::unique_ptr<stepper<T>> make_lpf_m(const scheme_spec& s, const Sys& sys) {
  if (s.nodes == "equispaced") return make_lpf_f<M, equispaced, Sys, T>(s, sys);
  if (s.nodes == "lobatto") return make_lpf_f<M, gauss_lobatto, Sys, T>(s, sys);
  if (s.nodes == "chebyshev") return make_lpf_f<M, chebyshev_lobatto, Sys, T>(s, sys);
  if (s.nodes == "gauss-interior") return make_lpf_f<M, gauss_interior, Sys, T>(s, sys);
  throw std::invalid_argument("unknown node family '" + s.nodes + "' (equispaced|lobatto|chebyshev|gauss-interior)");
}

/// Calls f.template operator()<M>() for the run-time m in 2..8.
template <class F>
auto with_m(int m, F&& f) {
  switch (m) {
    case 2: return f.template operator()<2>();
    case 3: return f.template operator()<3>();
    case 4: return f.template operator()<4>();
    case 5: return f.template operator()<5>();
    case 6: return f.template operator()<6>();
    case 7: return f.template operator()<7>();
    case 8: return f.template operator()<8>();
    default: throw std::invalid_argument("m must be an integer in 2..8, got " + std::to_string(m));
  }
}

}  // namespace detail

template <class Sys, class T>
std::unique_ptr<stepper<T>> make_system_stepper(const scheme_spec& s) {
#if GEOMINT_STEPPER_STUB
  (void)s;
  throw std::invalid_argument(std::to_string(std::numeric_limits<T>::digits10) +
                              "-digit arithmetic is not compiled into this build (GEOMINT_RUN_MULTIPRECISION=OFF)");
#else
  const Sys sys{};
  if (s.scheme == "midpoint") return detail::make_scheme<midpoint_vi, Sys, T>(sys);
  if (s.scheme == "trapezoidal") return detail::make_scheme<trapezoidal_vi, Sys, T>(sys);
  if (s.scheme == "galerkin")
    return detail::with_m(s.m, [&]<int M>() { return detail::make_scheme<galerkin_vi<M>, Sys, T>(sys); });
  if (s.scheme == "lpf") return detail::with_m(s.m, [&]<int M>() { return detail::make_lpf_m<M, Sys, T>(s, sys); });
  throw std::invalid_argument("unknown scheme '" + s.scheme + "' (lpf|midpoint|trapezoidal|galerkin)");
#endif
}

}  // namespace geomint::tools
