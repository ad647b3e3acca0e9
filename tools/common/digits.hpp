#pragma once
/// `--digits D` of the tools, now installed library code (geomint/cli/digits.hpp), under the
/// names the tools use.
#include "geomint/cli/digits.hpp"

namespace geomint::tools {
using cli::digits_of;
using cli::scalar_for_digits;
using cli::with_digits;
}  // namespace geomint::tools
