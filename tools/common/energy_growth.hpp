#pragma once
/// The energy error's growth fit, now installed library code (geomint/cli/energy_growth.hpp),
/// under the name the tools use.
#include "geomint/cli/energy_growth.hpp"

namespace geomint::tools {
using cli::energy_growth;
}  // namespace geomint::tools
