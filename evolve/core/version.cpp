#include "evolve/core/version.hpp"

namespace robozoo {

std::string version_line() {
  return std::string("robozoo ") + project_version_string() + ", git " + software_version_string();
}

}  // namespace robozoo
