#pragma once
/// Umbrella header: everything geomint provides.
#include "geomint/core/rational.hpp"
#include "geomint/core/polynomial.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/core/basis.hpp"
#include "geomint/core/differentiation.hpp"
#include "geomint/core/multiprecision.hpp"
#include "geomint/lie/so3.hpp"
#include "geomint/lie/se3.hpp"
#include "geomint/beam/beam.hpp"
