#pragma once
// ODE library initialisation: dInitODE2 exactly once per process, and ODE's
// per-thread data for the calling thread. The only process-wide state the
// simulation keeps is ODE's own.

namespace robozoo {

/// Safe to call any number of times from any thread.
void ensure_ode_initialized();

}  // namespace robozoo
