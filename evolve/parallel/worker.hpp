#pragma once
// The worker side of the protocol, independent of the transport: what a worker
// does with one frame it received. A pipe child runs it in a read/reply loop; an
// MPI rank would run the same function on each message it receives.
#include <functional>
#include <optional>

#include "evolve/parallel/protocol.hpp"

namespace robozoo {

/// The work a worker does: job payload in, result payload out. It must be a pure
/// function of its payload (and of state fixed before the pool started), since a
/// job may run in any worker and may run again after a crash.
using WorkFn = std::function<Bytes(const Bytes&)>;

/// Runs one job. An exception from fn becomes a failed Result carrying its message.
Result run_job(const WorkFn& fn, const Job& job);

/// Handles one frame received by a worker: a Job frame gives the encoded Result (or
/// Failure) frame to send back; a Shutdown frame gives nothing (the worker exits).
/// Any other frame is a ProtocolError.
std::optional<Bytes> serve_frame(const WorkFn& fn, Frame frame);

}  // namespace robozoo
