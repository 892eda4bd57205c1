#include "evolve/record/checkpoint.hpp"

#include "evolve/core/json_fields.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "evolve/neat/population_json.hpp"

namespace robozoo {

std::string checkpoint_path_for(const std::string& log_path) { return log_path + ".checkpoint"; }

namespace {
std::runtime_error sys_error(const std::string& path, const std::string& what) {
  return std::runtime_error(path + ": " + what + " (" + std::strerror(errno) + ")");
}

std::string folder_of(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}
}  // namespace

void write_file_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw sys_error(tmp, "cannot create");
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const auto err = sys_error(tmp, "write failed");
      ::close(fd);
      ::unlink(tmp.c_str());
      throw err;
    }
    done += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const auto err = sys_error(tmp, "cannot flush");
    ::unlink(tmp.c_str());
    throw err;
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const auto err = sys_error(path, "cannot rename the temporary file into place");
    ::unlink(tmp.c_str());
    throw err;
  }
  const int dfd = ::open(folder_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

std::string checkpoint_to_text(const Checkpoint& c) {
  nlohmann::json j;
  j["format"] = "robozoo-checkpoint";
  j["format_version"] = Checkpoint::kFormatVersion;
  j["run_id"] = c.run_id;
  j["software_version"] = c.software_version;
  j["config"] = c.config;
  j["population"] = population_state_to_json(c.population);
  j["rng_state"] = c.rng_state;
  j["evaluations"] = c.evaluations;
  j["best_so_far"] = c.best_so_far;
  j["last_champion_hash"] = c.last_champion_hash;
  j["log_bytes"] = c.log_bytes;
  j["log_events"] = c.log_events;
  j["elapsed_seconds"] = c.elapsed_seconds;
  j["finished"] = c.finished;
  if (c.log_continues) j[kLogContinuesKey] = log_continuation_to_json(*c.log_continues);
  return j.dump();
}

void write_checkpoint(const std::string& path, const Checkpoint& c) { write_file_atomic(path, checkpoint_to_text(c)); }

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the checkpoint");
  std::stringstream ss;
  ss << in.rdbuf();
  return checkpoint_from_text(ss.str(), path);
}

Checkpoint checkpoint_from_text(const std::string& text, const std::string& path) {
  using namespace json_fields;
  try {
    const auto j = nlohmann::json::parse(text);
    if (!j.is_object() || j.value("format", "") != "robozoo-checkpoint")
      throw std::runtime_error("not a robozoo checkpoint");
    const int64_t version = as_i64(field(j, "format_version", "checkpoint"), "checkpoint.format_version");
    if (version != Checkpoint::kFormatVersion)
      throw std::runtime_error("checkpoint format version " + std::to_string(version) + " is not the supported " +
                               std::to_string(Checkpoint::kFormatVersion) +
                               (version < Checkpoint::kFormatVersion
                                    ? " (written by an older robozoo, before node genes had drawing positions and the "
                                      "HyperNEAT topology rules; it cannot be resumed: start the run again)"
                                    : " (written by a newer robozoo)"));
    const std::string p = "checkpoint";
    Checkpoint c;
    c.run_id = as_string(field(j, "run_id", p), p + ".run_id");
    c.software_version = as_string(field(j, "software_version", p), p + ".software_version");
    c.config = field(j, "config", p);
    c.population = population_state_from_json(field(j, "population", p));
    c.rng_state = as_string(field(j, "rng_state", p), p + ".rng_state");
    c.evaluations = as_i64(field(j, "evaluations", p), p + ".evaluations");
    c.best_so_far = as_double(field(j, "best_so_far", p), p + ".best_so_far");
    c.last_champion_hash = as_u64(field(j, "last_champion_hash", p), p + ".last_champion_hash");
    c.log_bytes = as_i64(field(j, "log_bytes", p), p + ".log_bytes");
    c.log_events = as_i64(field(j, "log_events", p), p + ".log_events");
    c.elapsed_seconds = as_double(field(j, "elapsed_seconds", p), p + ".elapsed_seconds");
    c.finished = as_bool(field(j, "finished", p), p + ".finished");
    if (j.contains(kLogContinuesKey))
      c.log_continues = log_continuation_from_json(j.at(kLogContinuesKey), p + "." + kLogContinuesKey);
    if (c.log_bytes < 0 || c.log_events < 0 || c.evaluations < 0) throw std::runtime_error("negative counts");
    return c;
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": malformed checkpoint: " + e.what());
  }
}

}  // namespace robozoo
