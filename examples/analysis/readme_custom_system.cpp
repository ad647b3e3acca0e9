#include <geomint/geomint.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <iostream>

struct spring_pendulum {  // q = (r, phi): L = (rdot^2 + r^2 phidot^2)/2 - (r - 1)^2/2 + r cos(phi)
  static constexpr int dof = 2;
  template <class S>
  S operator()(const geomint::vec<S, 2>& q, const geomint::vec<S, 2>& v) const {
    using std::cos;  // call math functions unqualified
    return (v[0] * v[0] + q[0] * q[0] * v[1] * v[1]) / 2 - (q[0] - 1) * (q[0] - 1) / 2 + q[0] * cos(q[1]);
  }
};

template <class T>
void run() {
  geomint::integrator<geomint::galerkin_vi<3>, spring_pendulum, T> I(spring_pendulum{}, T(1) / 10);
  const geomint::vec<T, 2> q0(T(11) / 10, T(1) / 2), v0(T(0), T(0));
  auto s = I.initial_state(q0, v0);
  I.advance(s, 100);  // throws geomint::integration_error with the step index on failure
  auto orders = geomint::analysis::study_order(I, q0, v0, T(1), {4, 8, 16, 32});
  std::cout << "r(10) = " << s.q[0] << ", observed order " << orders.global_order
            << ", symplecticity defect " << geomint::analysis::symplecticity_defect(I, q0, v0, T(1) / 4) << "\n";
}

int main() { run<double>(); run<boost::multiprecision::cpp_bin_float_50>(); }
