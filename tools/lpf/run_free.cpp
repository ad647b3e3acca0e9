/// geomint-run's entry points for the free systems (the schemes come from geomint_steppers).
#include "run_impl.hpp"

namespace geomint::run {
int run_free_16(const options& o) { return run_free<tools::scalar_for_digits<16>>(o); }
int run_free_50(const options& o) { return run_free<tools::scalar_for_digits<50>>(o); }
int run_free_100(const options& o) { return run_free<tools::scalar_for_digits<100>>(o); }
}  // namespace geomint::run
