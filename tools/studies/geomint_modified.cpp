/// geomint-modified: the modified equation of a method and its prediction of the energy error,
/// the installed front end `modified` (geomint/cli/modified.hpp) over the tools' systems.
#include "geomint/cli/modified.hpp"
#include "stepper.hpp"

int main(int argc, char** argv) {
  return geomint::cli::modified_main(geomint::tools::free_system_types{}, argc, argv);
}
