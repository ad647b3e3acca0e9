#pragma once
/// The tools' progress line, now installed library code (geomint/cli/progress.hpp), under the
/// names the tools use.
#include "geomint/cli/progress.hpp"

namespace geomint::tools {
using cli::format_duration;
using cli::progress;
using cli::progress_line;
using cli::stderr_is_terminal;
}  // namespace geomint::tools
