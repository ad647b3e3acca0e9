#pragma once
/// Exact coefficients to a numeric scalar T at T's full precision: geomint::rational and
/// big_rational, exact_rational, field_element (methods/number_field.hpp) and algebraic_number
/// (methods/algebraic_number.hpp; for both the generator r computed once in T by bisection from
/// its rational bracket), and T itself.

#include <memory>
#include <type_traits>

#include "geomint/core/big_rational.hpp"
#include "geomint/core/rational.hpp"
#include "geomint/methods/algebraic_number.hpp"
#include "geomint/methods/number_field.hpp"

namespace geomint::methods {

/// Converts coefficients to T; remembers r in T for the field it last met (one converter per
/// thread).
template <class T>
class coefficient_converter {
 public:
  T operator()(const T& x) const { return x; }
  T operator()(const rational& x) const { return x.template to<T>(); }
  template <int L>
  T operator()(const big_rational<L>& x) const {
    return rational_to<T>(exact_rational(boost::multiprecision::cpp_int(x.num.str()), boost::multiprecision::cpp_int(x.den().str())));
  }
  T operator()(const exact_rational& x) const { return rational_to<T>(x); }
  T operator()(const field_element& x) const {
    if (!x.field()) return rational_to<T>(x.rational_value());
    if (x.field() != field_) {
      field_ = x.field();
      root_ = field_->template root_in<T>();
    }
    return x.template to<T>(root_);
  }
  /// Horner at r in T; each coefficient rounded once (r from root_in, once per field and T).
  template <auto P>
  T operator()(const algebraic_number<P>& x) const {
    static const T root = algebraic_number<P>::template root_in<T>();
    T s(0);
    for (int k = decltype(P)::degree - 1; k >= 0; --k) s = s * root + (*this)(x.coefficient(k));
    return s;
  }

 private:
  mutable std::shared_ptr<const algebraic_field> field_;
  mutable T root_{};
};

}  // namespace geomint::methods
