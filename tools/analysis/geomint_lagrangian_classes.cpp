/// geomint-lagrangian-classes: for which Lagrangians is each scheme symplectic? The numerical
/// symplecticity defect max |J^T Omega J - Omega| of one step (analysis::symplecticity_defect,
/// the function behind geomint-symplectic) in cpp_bin_float_50 at tau = 1/4, for every built-in
/// and zoo system, of LPF m = 3 on the Gauss interior nodes (its interior nodes are the two Gauss
/// points: a symplectic RKN method for natural systems), and the Galerkin VI m = 2 (the same
/// two Gauss points, variational). The difference Jacobian is accurate to about
/// eps^(4/5) ~ 1e-40: a defect there is symplectic, a defect far above it is not.
/// Output: CSV system,class,scheme,defect. Usage: geomint-lagrangian-classes (no options).
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <iostream>
#include <string>
#include <string_view>

#include "cli.hpp"
#include "geomint/analysis/any_system.hpp"
#include "geomint/integrator.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/zoo.hpp"

namespace {

using T = boost::multiprecision::cpp_bin_float_50;

template <class Scheme, class Sys>
void row(std::string_view system, std::string_view lagrangian_class, std::string_view scheme, const geomint::vec<T, Sys::dof>& q0,
         const geomint::vec<T, Sys::dof>& v0) {
  std::cout << system << ',' << lagrangian_class << ',' << scheme << ',';
  try {
    geomint::integrator<Scheme, Sys, T> I(Sys{}, T(1) / T(4));
    std::cout << static_cast<double>(geomint::analysis::symplecticity_defect(I, q0, v0, T(1) / T(4))) << '\n';
  } catch (const std::exception& e) {
    std::cout << "failed: " << e.what() << '\n';
  }
}

template <class Sys>
void system_rows(std::string_view system, std::string_view lagrangian_class, const geomint::vec<T, Sys::dof>& q0,
                 const geomint::vec<T, Sys::dof>& v0) {
  row<geomint::lpf<3, geomint::gauss_interior>, Sys>(system, lagrangian_class, "lpf m=3 gauss-interior", q0, v0);
  row<geomint::galerkin_vi<2>, Sys>(system, lagrangian_class, "galerkin m=2", q0, v0);
}

T frac(int n, int d) { return T(n) / T(d); }

}  // namespace

int main(int argc, char** argv) {
  geomint::cli::parser cl("geomint-lagrangian-classes",
                          "usage: geomint-lagrangian-classes (no options)\n"
                          "CSV system,class,scheme,defect: the symplecticity defect of one step of LPF m = 3\n"
                          "(Gauss interior nodes) and Galerkin m = 2, in 50 digits, at tau = 1/4.\n");
  if (const auto done = cl.parse(argc, argv)) return *done;
  namespace sys = geomint::systems;
  namespace zoo = geomint::zoo;
  using geomint::vec;
  std::cout.precision(3);
  std::cout << "system,class,scheme,defect\n";
  system_rows<sys::pendulum>("pendulum", "natural", vec<T, 1>(T(1)), vec<T, 1>(frac(1, 2)));
  system_rows<sys::kepler>("kepler", "natural", vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), frac(6, 5)));
  system_rows<zoo::henon_heiles>("henon-heiles", "natural", vec<T, 2>(frac(1, 10), frac(-1, 10)), vec<T, 2>(frac(1, 10), frac(1, 10)));
  system_rows<zoo::toda3>("toda", "natural", vec<T, 3>(T(0), frac(1, 2), T(1)), vec<T, 3>(frac(1, 2), T(0), frac(-1, 2)));
  system_rows<zoo::spring_pendulum>("spring-pendulum", "mass matrix depends on q", vec<T, 2>(frac(11, 10), frac(1, 2)),
                                    vec<T, 2>(T(0), T(0)));
  system_rows<zoo::double_pendulum>("double-pendulum", "mass matrix depends on q", vec<T, 2>(frac(1, 2), T(1)),
                                    vec<T, 2>(T(0), T(0)));
  system_rows<sys::charged>("charged", "linear in velocity (magnetic)", vec<T, 2>(T(1), T(0)), vec<T, 2>(T(0), frac(1, 2)));
  system_rows<zoo::arenstorf>("arenstorf", "linear in velocity (Coriolis)", vec<T, 2>(frac(1, 2), T(0)),
                              vec<T, 2>(T(0), frac(1, 2)));
  return geomint::cli::finish_stdout("geomint-lagrangian-classes");
}
