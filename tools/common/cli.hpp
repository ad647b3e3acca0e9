#pragma once
/// The tools' command-line parser and checked output, now installed library code
/// (geomint/cli/parser.hpp); this name is kept for the tools that include "cli.hpp".
#include "geomint/cli/parser.hpp"
