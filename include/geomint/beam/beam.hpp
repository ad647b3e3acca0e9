#pragma once
/// The geometrically exact beam (beam paper, sections 3-4): everything in one include.
#include "geomint/lie/se3.hpp"
#include "geomint/beam/material.hpp"
#include "geomint/beam/grid.hpp"
#include "geomint/beam/kernels.hpp"
#include "geomint/beam/paired_kernels.hpp"
#include "geomint/beam/integrator.hpp"
#include "geomint/beam/paper_case.hpp"
