/// geomint-run's entry points for the free systems (the schemes come from geomint_steppers).
#include "run_impl.hpp"

namespace geomint::run {
int run_free_16(const options& o) { return run_free<double>(o); }
int run_free_50(const options& o) { return run_free<boost::multiprecision::cpp_bin_float_50>(o); }
int run_free_100(const options& o) { return run_free<boost::multiprecision::cpp_bin_float_100>(o); }
}  // namespace geomint::run
