/// geomint-run's entry points for the free systems (the schemes come from geomint_steppers).
#include "run_impl.hpp"

namespace geomint::run {
template <int Digits>
int run_free(const options& o) {
  return run_free_system<tools::scalar_for_digits<Digits>>(o);
}
template int run_free<16>(const options&);
template int run_free<50>(const options&);
template int run_free<100>(const options&);
}  // namespace geomint::run
