#pragma once
/// Umbrella header: every public header of geomint, module by module (docs/design.md).

// core: exact arithmetic, polynomials, nodes, bases, differentiation weights
#include "geomint/core/rational.hpp"
#include "geomint/core/polynomial.hpp"
#include "geomint/core/nodes.hpp"
#include "geomint/core/basis.hpp"
#include "geomint/core/differentiation.hpp"
#include "geomint/core/multiprecision.hpp"
// ad, linalg, solvers: forward-mode AD, small dense linear algebra, Newton
#include "geomint/ad/dual.hpp"
#include "geomint/linalg/types.hpp"
#include "geomint/linalg/lu_small.hpp"
#include "geomint/solvers/newton.hpp"
// mechanics: system concepts, Lagrangian derivatives, constraints, built-in systems
#include "geomint/mechanics/lagrangian.hpp"
#include "geomint/mechanics/constraint.hpp"
#include "geomint/mechanics/systems.hpp"
#include "geomint/mechanics/constrained_systems.hpp"
#include "geomint/mechanics/zoo.hpp"
// schemes and the integrators built on them
#include "geomint/schemes/lpf.hpp"
#include "geomint/schemes/classical.hpp"
#include "geomint/schemes/constrained_lpf.hpp"
#include "geomint/schemes/paper_schemes.hpp"
#include "geomint/schemes/paper23.hpp"
#include "geomint/integrator.hpp"
// Lie groups and the geometrically exact beam
#include "geomint/lie/so3.hpp"
#include "geomint/lie/se3.hpp"
#include "geomint/beam/beam.hpp"
// exact and numerical analysis of the schemes
#include "geomint/analysis/exact_scheme.hpp"
#include "geomint/analysis/reference_flow.hpp"
#include "geomint/analysis/order_study.hpp"
#include "geomint/analysis/symplecticity.hpp"
#include "geomint/analysis/any_system.hpp"
