#pragma once
/// Reference flows for the order studies: the exact flow of the built-in free systems and of the
/// outer solar system (mechanics/zoo.hpp) by an adaptive Taylor series method in any scalar type.
///
/// Independence: the accelerations are written here in closed form (not through the Lagrangian
/// and the automatic differentiation used by the integrators):
/// - harmonic: a = -q;
/// - pendulum: a = -sin q;
/// - kepler:   a = -q |q|^-3;
/// - charged:  a = B(r) (v_y, -v_x) with B = 1 + r^2, the Lorentz force of B = curl A
///   (systems.hpp: A = a(r) (-y, x), a = (1 + r^2/2)/2);
/// - outer solar: a_i = G sum_{j != i} m_j (q_j - q_i) |q_j - q_i|^-3 (Newton's gravitation);
/// - henon-heiles: a = -(x + 2 x y, y + x^2 - y^2).
/// Taylor coefficients follow from the usual recurrences (Cauchy products; sin/cos pairs;
/// u^alpha: u_0 k w_k = sum_{j=1..k} ((alpha + 1) j - k) u_j w_{k-j}); the order N is about
/// -ln(eps)/2 and the step h = min_j (eps/|z_j|)^(1/j) / 2 over the last two coefficients
/// (Jorba & Zou 2005), so every step is accurate to about eps of the scalar type.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "geomint/core/checked_cast.hpp"
#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"

namespace geomint::analysis {

template <class Sys>
inline constexpr bool has_reference_flow =
    std::is_same_v<Sys, systems::harmonic> || std::is_same_v<Sys, systems::pendulum> ||
    std::is_same_v<Sys, systems::kepler> || std::is_same_v<Sys, systems::charged> ||
    std::is_same_v<Sys, zoo::outer_solar> || std::is_same_v<Sys, zoo::henon_heiles>;

namespace detail {

/// sum_{j=0..k} a_j b_{k-j}.
template <class T>
T cauchy(const std::vector<T>& a, const std::vector<T>& b, std::size_t k) {
  T out(0);
  for (std::size_t j = 0; j <= k; ++j) out += a[j] * b[k - j];
  return out;
}

/// w_k of w = u^(-3/2) from u_0..u_k and w_0..w_{k-1} (Kepler's and Newton's r^-3 with u = r^2):
/// u_0 k w_k = sum_{j=1..k} ((alpha + 1) j - k) u_j w_{k-j}, (alpha + 1) j - k = -(j + 2k)/2.
template <class T>
T inverse_cube_coefficient(const std::vector<T>& u, const std::vector<T>& w, std::size_t k) {
  if (k == 0) {
    using std::sqrt;
    return T(1) / (u[0] * sqrt(u[0]));
  }
  T sum(0);
  for (std::size_t j = 1; j <= k; ++j) sum -= from_int64<T>(static_cast<std::int64_t>(j + 2 * k)) * u[j] * w[k - j];
  return sum / (T(2) * from_int64<T>(static_cast<std::int64_t>(k)) * u[0]);
}

/// The order-k coefficient of the outer solar system's accelerations, from the position
/// coefficients q_0..q_k; `pairs` keeps each pair's series of q_j - q_i, |q_j - q_i|^2 and
/// |q_j - q_i|^-3 (one Cauchy product per component and pair).
template <class T>
struct n_body_series {
  static constexpr int bodies = zoo::outer_solar::bodies;
  struct pair {
    int i, j;
    std::array<std::vector<T>, 3> d;
    std::vector<T> r2, w;
  };
  std::vector<pair> pairs;
  std::array<T, bodies> gm;

  explicit n_body_series(std::size_t N) {
    const T G = zoo::outer_solar::gravitational_constant<T>();
    for (int b = 0; b < bodies; ++b) gm[std::size_t(b)] = G * zoo::outer_solar::mass<T>(b);
    for (int i = 0; i < bodies; ++i)
      for (int j = i + 1; j < bodies; ++j) {
        pair pr{i, j, {}, std::vector<T>(N + 1), std::vector<T>(N + 1)};
        for (auto& c : pr.d) c.assign(N + 1, T(0));
        pairs.push_back(std::move(pr));
      }
  }

  vec<T, 3 * bodies> acceleration(const std::vector<vec<T, 3 * bodies>>& q, std::size_t k) {
    vec<T, 3 * bodies> a = vec<T, 3 * bodies>::Zero();
    for (pair& pr : pairs) {
      for (int c = 0; c < 3; ++c) pr.d[std::size_t(c)][k] = q[k][3 * pr.j + c] - q[k][3 * pr.i + c];
      pr.r2[k] = cauchy(pr.d[0], pr.d[0], k) + cauchy(pr.d[1], pr.d[1], k) + cauchy(pr.d[2], pr.d[2], k);
      pr.w[k] = inverse_cube_coefficient(pr.r2, pr.w, k);
      for (int c = 0; c < 3; ++c) {
        const T f = cauchy(pr.d[std::size_t(c)], pr.w, k);
        a[3 * pr.i + c] += gm[std::size_t(pr.j)] * f;
        a[3 * pr.j + c] -= gm[std::size_t(pr.i)] * f;
      }
    }
    return a;
  }
};

/// Taylor coefficients q_0..q_N, v_0..v_N of the solution of qddot = a(q, qdot) through
/// (q_0, v_0), for the system's closed-form acceleration.
template <class Sys, class T>
void taylor_coefficients(const vec<T, Sys::dof>& q0, const vec<T, Sys::dof>& v0, std::size_t N,
                         std::vector<vec<T, Sys::dof>>& q, std::vector<vec<T, Sys::dof>>& v) {
  static_assert(has_reference_flow<Sys>, "geomint::analysis: no closed-form reference flow for this system");
  constexpr int n = Sys::dof;
  using V = vec<T, n>;
  q.assign(N + 1, V::Zero());
  v.assign(N + 1, V::Zero());
  q[0] = q0;
  v[0] = v0;
  // Auxiliary series: pendulum sin/cos q; kepler and charged r^2 = x^2 + y^2 and w = r^-3.
  std::vector<T> s(N + 1), c(N + 1), x(N + 1), y(N + 1), vx(N + 1), vy(N + 1), r2(N + 1), w(N + 1);
  std::optional<n_body_series<T>> bodies;
  if constexpr (std::is_same_v<Sys, zoo::outer_solar>) bodies.emplace(N);
  for (std::size_t k = 0; k < N; ++k) {
    V a;
    if constexpr (std::is_same_v<Sys, zoo::outer_solar>) {
      a = bodies->acceleration(q, k);
    } else if constexpr (std::is_same_v<Sys, systems::harmonic>) {
      a = -q[k];
    } else if constexpr (std::is_same_v<Sys, systems::pendulum>) {
      using std::cos;
      using std::sin;
      if (k == 0) {
        s[0] = sin(q[0][0]);
        c[0] = cos(q[0][0]);
      } else {
        T ss(0), cc(0);
        for (std::size_t j = 1; j <= k; ++j) {
          ss += from_int64<T>(static_cast<std::int64_t>(j)) * q[j][0] * c[k - j];
          cc += from_int64<T>(static_cast<std::int64_t>(j)) * q[j][0] * s[k - j];
        }
        s[k] = ss / from_int64<T>(static_cast<std::int64_t>(k));
        c[k] = -cc / from_int64<T>(static_cast<std::int64_t>(k));
      }
      a[0] = -s[k];
    } else {
      x[k] = q[k][0];
      y[k] = q[k][1];
      vx[k] = v[k][0];
      vy[k] = v[k][1];
      r2[k] = cauchy(x, x, k) + cauchy(y, y, k);
      if constexpr (std::is_same_v<Sys, zoo::henon_heiles>) {
        a[0] = -(x[k] + T(2) * cauchy(x, y, k));
        a[1] = -(y[k] + cauchy(x, x, k) - cauchy(y, y, k));
      } else if constexpr (std::is_same_v<Sys, systems::kepler>) {
        w[k] = inverse_cube_coefficient(r2, w, k);
        a[0] = -cauchy(x, w, k);
        a[1] = -cauchy(y, w, k);
      } else {
        // B = 1 + r^2; a = B (v_y, -v_x).
        w[k] = r2[k] + (k == 0 ? T(1) : T(0));
        a[0] = cauchy(w, vy, k);
        a[1] = -cauchy(w, vx, k);
      }
    }
    const T next = from_int64<T>(static_cast<std::int64_t>(k + 1));
    v[k + 1] = a / next;
    q[k + 1] = v[k] / next;
  }
}

}  // namespace detail

/// The exact flow of Sys in the scalar T (q, qdot and p = dL/dqdot), to about eps of T.
template <class Sys, class T>
class reference_flow {
 public:
  static constexpr int n = Sys::dof;
  using V = vec<T, n>;

  /// Starts at (q0, p0); the velocity is recovered from p0 (inverse Legendre transform).
  reference_flow(const V& q0, const V& p0, const Sys& sys = Sys{}) : sys_(sys), q_(q0) {
    if (!geomint::all_finite(q0) || !geomint::all_finite(p0))
      throw std::invalid_argument("geomint::reference_flow: non-finite initial state");
    if (!geomint::lagrangian_derivatives<Sys, T>::velocity(sys_, q0, p0, v_))
      throw std::invalid_argument("geomint::reference_flow: cannot recover the velocity from p0");
    using std::log;
    order_ = std::max<std::size_t>(
        8, integer_or_throw<std::size_t>(T(-log(std::numeric_limits<T>::epsilon()) / T(2)), "geomint::reference_flow: order") + 2);
  }

  const T& time() const { return t_; }
  const V& q() const { return q_; }
  const V& qdot() const { return v_; }
  V p() const { return momentum<Sys, T>(sys_, q_, v_); }
  long steps() const { return steps_; }

  /// The step bound of advance_to unless the caller gives one: 10^8 Taylor steps.
  static constexpr long default_max_steps = 100'000'000L;

  /// Advances to t_end >= time() in at most max_steps steps, bounded up front: throws
  /// std::length_error before the first step when t_end - time() is more than max_steps steps
  /// of the current step size (an estimate: the step size follows the local Taylor
  /// coefficients), and std::runtime_error if the bound is reached anyway or a step no longer
  /// advances the time (t + h == t: t_end is beyond the resolution of T at this step size). The
  /// state is then that of the last step taken.
  void advance_to(const T& t_end, long max_steps = default_max_steps) {
    using geomint::detail::short_number;
    check_end(t_end);
    if (t_ < t_end) {
      const T estimate = estimated_steps(t_end);
      if (estimate > from_int64<T>(max_steps))
        throw std::length_error("geomint::reference_flow: t_end - t = " +
                                short_number(geomint::detail::approximately(T(t_end - t_))) + " needs about " +
                                short_number(geomint::detail::approximately(estimate)) +
                                " Taylor steps, more than the bound " + std::to_string(max_steps));
    }
    if (!advance_toward(t_end, max_steps))
      throw std::runtime_error("geomint::reference_flow: " + std::to_string(max_steps) + " Taylor steps end at t = " +
                               short_number(geomint::detail::approximately(t_)) + ", before t_end = " +
                               short_number(geomint::detail::approximately(t_end)));
  }

  /// (t_end - time()) / h for the step size h at the current state: the number of steps to
  /// t_end if the step size stayed as it is (0 when t_end <= time()).
  T estimated_steps(const T& t_end) {
    if (!(t_ < t_end)) return T(0);
    return (t_end - t_) / step_size();
  }

  /// At most max_steps steps toward t_end >= time(); true once time() == t_end. For callers
  /// that bound a run by time (check the clock between calls). Throws std::runtime_error when a
  /// step no longer advances the time (t + h == t).
  bool advance_toward(const T& t_end, long max_steps) {
    check_end(t_end);
    for (long k = 0; k < max_steps && t_ < t_end; ++k) {
      T h = step_size();
      const bool last = !(t_ + h < t_end);
      if (last) h = t_end - t_;
      else if (!(t_ + h > t_))
        throw std::runtime_error("geomint::reference_flow: the step " +
                                 geomint::detail::short_number(geomint::detail::approximately(h)) + " no longer advances t = " +
                                 geomint::detail::short_number(geomint::detail::approximately(t_)) +
                                 " (t + h == t): t_end is beyond the resolution of the scalar");
      V qn = qc_[order_], vn = vc_[order_];
      for (std::size_t j = order_; j-- > 0;) {
        qn = qn * h + qc_[j];
        vn = vn * h + vc_[j];
      }
      if (!geomint::all_finite(qn) || !geomint::all_finite(vn))
        throw std::runtime_error("geomint::reference_flow: the Taylor series diverged");
      q_ = qn;
      v_ = vn;
      t_ = last ? t_end : t_ + h;
      steps_ = checked_add(steps_, 1L).value_or(std::numeric_limits<long>::max());  // a count: saturates
    }
    return !(t_ < t_end);
  }

 private:
  void check_end(const T& t_end) const {
    if (!geomint::is_finite(t_end) || t_end < t_) throw std::invalid_argument("geomint::reference_flow: bad end time");
  }
  /// The Taylor coefficients at the current state (into qc_, vc_) and the step size
  /// h = min_j (eps/|z_j|)^(1/j) / 2 over the last two (Jorba & Zou 2005); infinite when both vanish.
  T step_size() {
    using std::pow;
    detail::taylor_coefficients<Sys, T>(q_, v_, order_, qc_, vc_);
    const T eps = std::numeric_limits<T>::epsilon();
    T h = std::numeric_limits<T>::infinity();
    for (std::size_t j : {order_ - 1, order_}) {
      const T size = std::max(qc_[j].template lpNorm<Eigen::Infinity>(), vc_[j].template lpNorm<Eigen::Infinity>());
      if (size > T(0)) h = std::min(h, pow(eps / size, T(1) / from_int64<T>(static_cast<std::int64_t>(j))));
    }
    return h / T(2);
  }

  Sys sys_;
  V q_, v_;
  T t_ = T(0);
  std::size_t order_;
  long steps_ = 0;
  std::vector<V> qc_, vc_;
};

}  // namespace geomint::analysis
