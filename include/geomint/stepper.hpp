#pragma once
/// The one step interface (any_stepper, solvers/any_stepper.hpp) over the library's schemes: an
/// integrator erased (`erase`), or a scheme chosen at run time by name (`make_stepper`), what a
/// program needs that picks the scheme from a command line or a table (the tools, the studies).
/// Every step runs the same checks as `integrator::try_step` (solvers/phase_state.hpp), and a
/// failed step leaves (q1, p1) untouched.
///
///   auto s = geomint::make_stepper<geomint::systems::pendulum, double>({"lpf", "gauss_interior", "lagrange", 4});
///   geomint::step_status st = s->try_step(q, p, tau, q1, p1);
///   auto e = geomint::erase(I);   // I: an integrator<Scheme, Sys, T>
///
/// `make_stepper<Sys, T>` instantiates every scheme a spec can name for one (Sys, T): LPF for
/// m = 2..8 on the six node families and both bases, Galerkin for m = 2..8, midpoint and
/// trapezoidal: 93 schemes over 16 engines (the node families and bases of one LPF method are
/// data of one engine, `engine_stepper`); on a natural system also LPF's fixed-point form for
/// m = 2..8 (`lpf-fixed-point`, schemes/lpf_fixed_point.hpp: 7 more engines). That is some 30 s of GCC
/// 12 CPU time per (Sys, T) (the 12 units of tools/common: 28-34 s each; scripts/compile_times.sh), so
/// a program instantiates it once per (Sys, T): `extern template` where it is used, `template`
/// in one source file (as tools/common/stepper_tu.cpp does).

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "geomint/core/dispatch.hpp"
#include "geomint/integrator.hpp"
#include "geomint/schemes/lpf_fixed_point.hpp"
#include "geomint/schemes/registry.hpp"
#include "geomint/schemes/resolution.hpp"
#include "geomint/solvers/any_stepper.hpp"
#include "geomint/solvers/phase_state.hpp"

namespace geomint {

/// The range of m a stepper accepts (the schemes it can be made of: schemes/registry.hpp).
inline constexpr int stepper_min_m = 2;
inline constexpr int stepper_max_m = 8;
/// Why lpf-fixed-point has no stepper on a system that is not natural.
inline constexpr std::string_view fixed_point_natural_only =
    "lpf-fixed-point needs a natural system (L = qdot^T M qdot / 2 - V(q), mechanics/lagrangian.hpp)";

/// A scheme chosen by name: `nodes` and `basis` apply to lpf only (lpf-fixed-point is on
/// Gauss-interior nodes), `m` to lpf, lpf-fixed-point and galerkin. Node families are accepted
/// under either spelling (core/dispatch.hpp).
struct scheme_spec {
  std::string scheme = "lpf";
  std::string nodes = "equispaced";
  std::string basis = "lagrange";
  int m = 2;
  /// Whether the scheme has an m (midpoint and trapezoidal have none; schemes/registry.hpp).
  bool has_m() const {
    const scheme_entry* e = find_scheme(scheme);
    return e && e->has_m;
  }
  /// The node family column of tables: the printed family name, or "-" where it does not apply.
  std::string nodes_label() const {
    const scheme_entry* e = find_scheme(scheme);
    if (e && !e->fixed_nodes.empty()) return std::string(e->fixed_nodes);
    if (!e || !e->has_nodes) return "-";
    const auto family = canonical_node_family(nodes);
    return family ? std::string(*family) : nodes;
  }
};

namespace detail {
/// The engine a stepper holds for a scheme engine E: its step skeleton where it has one (the
/// schemes that differ only in their data, such as the node families of an LPF method, share
/// it), else E itself.
template <class E>
struct stepper_engine {
  using type = E;
};
template <class E>
  requires requires { typename E::skeleton_type; }
struct stepper_engine<E> {
  using type = typename E::skeleton_type;
};
template <class Scheme, class Sys, class T>
using stepper_engine_t = typename stepper_engine<typename Scheme::template engine<Sys, T>>::type;
}  // namespace detail

/// The stepper over one engine type on one system, compiled once per (engine, Sys, T) whatever
/// the number of schemes that share the engine.
template <class Engine, class Sys, class T>
class engine_stepper : public any_stepper<T> {
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;
  using typename any_stepper<T>::vector;

 public:
  /// `resolution_bound`: the scheme's bound on tau * omega_max (scheme_resolution_bound).
  engine_stepper(const Sys& sys, Engine engine, std::string name, const T& resolution_bound)
      : any_stepper<T>(resolution_bound), sys_(sys), engine_(std::move(engine)), name_(std::move(name)) {}
  int dof() const override { return n; }
  std::string name() const override { return name_; }

  T energy(const vector& q, const vector& p) const override { return energy_qp<Sys, T>(sys_, fixed(q), fixed(p)); }
  vector momentum(const vector& q, const vector& qdot) const override {
    return geomint::momentum<Sys, T>(sys_, fixed(q), fixed(qdot));
  }

 protected:
  step_status step(const vector& q, const vector& p, const T& tau, vector& q1, vector& p1,
                   const newton_options<T>& opt) override {
    phase_state<T, n> s;
    s.q = fixed(q);
    s.p = fixed(p);
    const step_status st = check_step_input(s.step, tau, s.q, s.p);
    if (!st) return st;
    V q1f = V::Zero(), p1f = V::Zero();
    const step_status done =
        finish_step(s, engine_.one_step(s.q, s.p, tau, q1f, p1f, opt, &cache_), q1f, p1f, tau, this->monitor_, sys_);
    if (done) {
      q1 = s.q;
      p1 = s.p;
    }
    return done;
  }
  step_status step_compensated(const vector& q, const vector& p, vector& q_carry, vector& p_carry, const T& tau,
                               vector& q1, vector& p1, const newton_options<T>& opt) override {
    phase_state<T, n> s;
    s.q = fixed(q);
    s.p = fixed(p);
    const step_status st = check_step_input(s.step, tau, s.q, s.p);
    if (!st) return st;
    phase_carry<T, n> carry1;
    carry1.q = fixed(q_carry);
    carry1.p = fixed(p_carry);
    V q1f = V::Zero(), p1f = V::Zero();
    const step_status done =
        finish_step(s, engine_.one_step(s.q, s.p, tau, q1f, p1f, opt, &cache_, nullptr, &carry1), q1f, p1f, tau, this->monitor_,
                    sys_, &carry1);
    if (done) {
      q1 = s.q;
      p1 = s.p;
      q_carry = s.carry.q;
      p_carry = s.carry.p;
    }
    return done;
  }
 private:
  static V fixed(const vector& x) {
    if (x.size() != n)
      throw std::invalid_argument("geomint::any_stepper: a vector of size " + std::to_string(x.size()) + " for a system with " +
                                  std::to_string(n) + " degrees of freedom");
    return V(x);
  }
  Sys sys_;
  Engine engine_;
  typename Engine::cache_type cache_;
  std::string name_;
};

namespace detail {
/// The engine_stepper that runs Scheme.
template <class Scheme, class Sys, class T>
using engine_stepper_of = engine_stepper<stepper_engine_t<Scheme, Sys, T>, Sys, T>;
}  // namespace detail

/// The stepper of one scheme (a type such as `lpf<4, gauss_interior>`) on one system.
template <class Scheme, class Sys, class T>
class scheme_stepper final : public detail::engine_stepper_of<Scheme, Sys, T> {
 public:
  explicit scheme_stepper(const Sys& sys = Sys{})
      : detail::engine_stepper_of<Scheme, Sys, T>(sys, typename Scheme::template engine<Sys, T>(sys), Scheme::name(),
                                                  scheme_resolution_bound<Scheme, T>()) {}
};

/// The stepper of `Scheme` on `sys` as an engine_stepper (no class of its own per scheme).
template <class Scheme, class Sys, class T>
std::unique_ptr<any_stepper<T>> make_scheme_stepper(const Sys& sys = Sys{}) {
  return std::make_unique<detail::engine_stepper_of<Scheme, Sys, T>>(
      sys, typename Scheme::template engine<Sys, T>(sys), Scheme::name(), scheme_resolution_bound<Scheme, T>());
}

/// The integrator I, erased: a stepper of its scheme on its system, with its Newton options
/// and its step monitor, and a cache of its own (I's cache and its compensated-summation
/// switch stay with I; the stepper's compensated steps are try_step_compensated).
template <class Scheme, class Sys, class T>
std::unique_ptr<any_stepper<T>> erase(const integrator<Scheme, Sys, T>& I) {
  auto s = make_scheme_stepper<Scheme, Sys, T>(I.system_ref());
  s->set_options(I.options());
  s->set_monitor(I.monitor());
  return s;
}

/// The stepper named by `spec` on `sys`; std::invalid_argument for an unknown scheme, node
/// family or basis, m outside stepper_min_m..stepper_max_m, or lpf-fixed-point on a system that
/// is not natural.
template <class Sys, class T>
std::unique_ptr<any_stepper<T>> make_stepper(const scheme_spec& spec, const Sys& sys = Sys{}) {
  auto make = [&]<class Scheme>() -> std::unique_ptr<any_stepper<T>> { return make_scheme_stepper<Scheme, Sys, T>(sys); };
  auto with_m = [&](auto&& f) {
    try {
      return with_int<stepper_min_m, stepper_max_m>(spec.m, f);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("m ") + e.what());
    }
  };
  if (spec.scheme == "midpoint") return make.template operator()<midpoint_vi>();
  if (spec.scheme == "trapezoidal") return make.template operator()<trapezoidal_vi>();
  if (spec.scheme == "galerkin") return with_m([&]<int M>() { return make.template operator()<galerkin_vi<M>>(); });
  if (spec.scheme == "lpf-fixed-point") {
    if constexpr (natural_system<Sys>)
      return with_m([&]<int M>() { return make.template operator()<lpf_fixed_point<M>>(); });
    else
      throw std::invalid_argument(std::string(fixed_point_natural_only));
  }
  if (spec.scheme == "lpf")
    return with_m([&]<int M>() {
      return with_node_family(spec.nodes, [&]<class Family>() {
        return with_basis(spec.basis, [&]<class Basis>() { return make.template operator()<lpf<M, Family, Basis>>(); });
      });
    });
  throw std::invalid_argument("unknown scheme '" + spec.scheme + "' (" +
                              scheme_choices() + ")");
}

}  // namespace geomint
