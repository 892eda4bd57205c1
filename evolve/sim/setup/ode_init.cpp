#include "evolve/sim/setup/ode_init.hpp"

#include <mutex>
#include <stdexcept>

#include <ode/ode.h>

namespace robozoo {

void ensure_ode_initialized() {
  static std::once_flag once;  // guards ODE's own process-wide initialisation
  std::call_once(once, [] {
    if (!dInitODE2(0)) throw std::runtime_error("dInitODE2 failed");
  });
  if (!dAllocateODEDataForThread(dAllocateMaskAll)) throw std::runtime_error("dAllocateODEDataForThread failed");
}

}  // namespace robozoo
