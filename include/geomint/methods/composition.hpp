#pragma once
/// A composition of a base method as data: the steps gamma_1 h, ..., gamma_k h of the base
/// method in turn (Yoshida 1990, Phys. Lett. A 150, 262-268; Hairer, Lubich & Wanner 2006,
/// section II.4; docs/references.md). It runs through the same integrator as any tableau: its
/// stages are those of the k sub-steps (methods/nystrom_form.hpp, nystrom_form_of).
///
///   auto r = field_element::generator(algebraic_field::make({-2, 0, 0, 1}));  // 2^(1/3)
///   composition<rkn<field_element, 2>, 3> triple_jump{verlet, {1 / (2 - r), -r / (2 - r), 1 / (2 - r)}};

#include <array>
#include <cstddef>

namespace geomint::methods {

template <class Base, int K>
struct composition {
  static_assert(K >= 1, "geomint::methods::composition: at least one sub-step");
  using base_type = Base;
  using coefficient = typename Base::coefficient;
  static constexpr int steps = K;
  Base base;
  std::array<coefficient, static_cast<std::size_t>(K)> gamma{};
};

}  // namespace geomint::methods
