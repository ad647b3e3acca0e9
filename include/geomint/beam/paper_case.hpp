#pragma once
/// The test case of the beam paper, section 4 (docs/design.md, "Beam conventions"):
///   l = 2 pi/3, a = 0.1, rho = 1000, E = 1e7, nu = 0.35, dt = 1e-4, J + 1 = 101 nodes,
///   mu_j^0 = (0,0,0, a^2 rho sin(j pi/J), a^2 rho, 0)   (the paper writes sin(j pi/100), J = 100),
///   gamma_{j+1/2}^0 = (-1,0,0, 0,0,0),   free ends gamma_{-1/2} = gamma_{J+1/2} = 0.
/// The initial configuration is the strain-consistent chain from g_0 = identity (the paper does
/// not state it; it only enters the momentum diagnostics and the centreline plots).

#include <boost/math/constants/constants.hpp>

#include "geomint/beam/integrator.hpp"

namespace geomint::beam {

template <class T>
struct paper_case {
  material<T> mat;
  staggered_grid<T> grid;
  std::vector<vec6<T>> mu0;
  std::vector<vec6<T>> gamma0;

  /// nodes = J + 1 (the paper: 101).
  explicit paper_case(int nodes = 101)
      : mat(material<T>::square_section(T(1) / T(10), T(1000), T(10000000), T(35) / T(100))),
        grid(T(2) * boost::math::constants::pi<T>() / T(3), nodes - 1) {
    using std::sin;
    const T a = T(1) / T(10), rho = T(1000);
    const T pi = boost::math::constants::pi<T>();
    const int J = grid.segments;
    mu0.resize(J + 1);
    for (int j = 0; j <= J; ++j) {
      mu0[j] << T(0), T(0), T(0), a * a * rho * sin(T(j) * pi / T(J)), a * a * rho, T(0);
    }
    gamma0.assign(J, vec6<T>::Zero());
    for (auto& g : gamma0) g(0) = T(-1);
  }

  /// The paper's time step, 1e-4 s.
  static T paper_dt() { return T(1) / T(10000); }

  integrator<T> make(const options<T>& opt) const { return integrator<T>(mat, grid, mu0, gamma0, opt); }
  integrator<T> make(scheme s = scheme::poisson) const {
    options<T> opt;
    opt.dt = paper_dt();
    opt.method = s;
    return make(opt);
  }
};

}  // namespace geomint::beam
