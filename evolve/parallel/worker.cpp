#include "evolve/parallel/worker.hpp"

#include <exception>
#include <string>

namespace robozoo {

Result run_job(const WorkFn& fn, const Job& job) {
  Result r;
  r.index = job.index;
  try {
    r.payload = fn(job.payload);
    r.ok = true;
  } catch (const std::exception& e) {
    r.ok = false;
    r.payload.clear();
    r.error = e.what();
    if (r.error.empty()) r.error = "exception with an empty message";
  } catch (...) {
    r.ok = false;
    r.payload.clear();
    r.error = "unknown exception (not derived from std::exception)";
  }
  return r;
}

std::optional<Bytes> serve_frame(const WorkFn& fn, Frame frame) {
  if (frame.kind == FrameKind::Shutdown) return std::nullopt;
  const Job job = job_from_frame(std::move(frame));  // throws on Result/Failure frames
  return encode_result(run_job(fn, job));
}

}  // namespace robozoo
