/// std::cos on the integrator's dual numbers: the message says to write `using std::cos;`.
#include <geomint/integrator.hpp>
struct pendulum {
  static constexpr int dof = 1;
  template <class S>
  S operator()(const geomint::vec<S, 1>& q, const geomint::vec<S, 1>& v) const {
#if GEOMINT_EXPECT_FAILURE
    return v[0] * v[0] / S(2) + std::cos(q[0]);
#else
    using std::cos;
    return v[0] * v[0] / S(2) + cos(q[0]);
#endif
  }
};
int main() {
  geomint::integrator<geomint::midpoint_vi, pendulum, double> integrator(pendulum{}, 0.1);
  auto s = integrator.initial_state(geomint::vec<double, 1>(1.0), geomint::vec<double, 1>(0.0));
  integrator.step(s);
  return s.step == 1 ? 0 : 1;
}
