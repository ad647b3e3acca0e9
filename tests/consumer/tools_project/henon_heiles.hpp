#pragma once
// The Henon-Heiles system of geomint's README, L = |qdot|^2 / 2 - (x^2 + y^2) / 2 - x^2 y + y^3 / 3,
// written as a natural system (L = qdot^T M qdot / 2 - V(q)), so that the schemes and tableau
// files for natural systems (lpf-fixed-point, rkn and prk tableaux) apply too, with the two
// members the command-line tools need: its name and its default initial data.
#include <string_view>

#include <geomint/geomint.hpp>

struct henon_heiles : geomint::natural<henon_heiles, 2> {
  static constexpr std::string_view name = "henon-heiles";
  /// V = (x^2 + y^2) / 2 + x^2 y - y^3 / 3.
  template <class S>
  static S potential(const geomint::vec<S, 2>& q) {
    const S& x = q[0];
    const S& y = q[1];
    return S((x * x + y * y) / S(2) + x * x * y - y * y * y / S(3));
  }
  /// M = identity.
  template <class S>
  static geomint::mat<S, 2> mass_matrix() {
    return geomint::mat<S, 2>::Identity();
  }
  /// q0 = (0, 0), qdot0 = (3/10, 2/5): energy 1/8.
  template <class T>
  static void initial_data(geomint::vec<T, 2>& q, geomint::vec<T, 2>& qdot) {
    q << T(0), T(0);
    qdot << T(3) / T(10), T(2) / T(5);
  }
};
