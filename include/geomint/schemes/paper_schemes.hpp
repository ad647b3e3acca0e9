#pragma once
/// The numbered schemes of Kong & Yang (2020), section 3, as geomint schemes, in one place.
///
/// (16), (18), (19) are LPF of degree m = 2, 3, 4 on equispaced nodes for the harmonic
/// oscillator; (17) is the classical midpoint-rule variational integrator it is compared with;
/// (21) and (22) are m = 2 in the Lagrange (eq. 8) and Bernstein (eq. 13) bases for the
/// pendulum. (23), the printed scheme for the particle on a circle, is schemes/paper23.hpp.

#include "geomint/schemes/classical.hpp"
#include "geomint/schemes/lpf.hpp"

namespace geomint {

using scheme16 = lpf<2, equispaced, lagrange>;
using scheme17 = midpoint_vi;
using scheme18 = lpf<3, equispaced, lagrange>;
using scheme19 = lpf<4, equispaced, lagrange>;
using scheme21 = lpf<2, equispaced, lagrange>;
using scheme22 = lpf<2, equispaced, bernstein>;

}  // namespace geomint
