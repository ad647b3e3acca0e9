/// Your own system, start to finish: one struct, integrated in double and in 50 digits, its
/// observed order measured and its symplecticity checked, with no adapter code.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <geomint/analysis/any_system.hpp>
#include <geomint/integrator.hpp>
#include <iostream>

/// A pendulum hanging from a spring (polar coordinates r, phi; unit constants):
/// L = 1/2 (rdot^2 + r^2 phidot^2) - 1/2 (r - 1)^2 + r cos(phi). A general system (the mass
/// matrix diag(1, r^2) depends on q); math functions are called unqualified.
struct spring_pendulum {
  static constexpr int dof = 2;
  template <class S>
  S operator()(const geomint::vec<S, 2>& q, const geomint::vec<S, 2>& v) const {
    using std::cos;
    return (v[0] * v[0] + q[0] * q[0] * v[1] * v[1]) / 2 - (q[0] - 1) * (q[0] - 1) / 2 + q[0] * cos(q[1]);
  }
};

template <class Scheme, class T>
void report(const char* label) {
  geomint::integrator<Scheme, spring_pendulum, T> I(spring_pendulum{}, T(1) / 10);
  const geomint::vec<T, 2> q0(T(11) / 10, T(1) / 2), v0(T(0), T(0));
  auto s = I.initial_state(q0, v0);
  const T e0 = I.energy(s);
  I.advance(s, 100);
  using std::abs;
  const auto orders = geomint::analysis::study_order(I, q0, v0, T(1), {4, 8, 16, 32});
  std::cout << label << ": q(10) = (" << s.q[0] << ", " << s.q[1] << "), |H - H0| = " << abs(I.energy(s) - e0)
            << "\n  observed global order " << orders.global_order << " (local " << orders.local_order << ")"
            << ", symplecticity defect at tau = 1/4: "
            << geomint::analysis::symplecticity_defect(I, q0, v0, T(1) / 4) << "\n";
}

int main() {
  using T50 = boost::multiprecision::cpp_bin_float_50;
  std::cout.precision(6);
  report<geomint::lpf<3, geomint::gauss_interior>, double>("LPF m=3 Gauss, double");
  report<geomint::lpf<3, geomint::gauss_interior>, T50>("LPF m=3 Gauss, 50 digits");
  report<geomint::galerkin_vi<3>, T50>("Galerkin m=3, 50 digits");
}
