#include "runlog/read/log_source.hpp"

#include <sys/stat.h>

#include <sstream>
#include <stdexcept>

#include "runlog/read/log_reader.hpp"

namespace robozoo {

std::vector<const RunRecord*> LoadedLog::runs() const {
  std::vector<const RunRecord*> out;
  for (const auto& r : collector->runs()) out.push_back(r.get());
  return out;
}

LoadedLog load_log(const std::string& path, const LoadOptions& options) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw std::runtime_error(path + ": no such log file");
  if (!S_ISREG(st.st_mode)) throw std::runtime_error(path + ": not a regular file");
  ScannedLog scanned;
  try {
    scanned = scan_event_log(path);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot read the log: " + e.what());
  }
  const LogContents& contents = scanned.contents;
  if (contents.records.empty())
    throw std::runtime_error(path + ": no LCM events in " + std::to_string(st.st_size) +
                             " bytes: not a robozoo-evolve log");
  const bool truncated = scanned.damaged_bytes() > 0;
  if (truncated && !options.allow_truncated)
    throw std::runtime_error(path + ": the log is truncated or damaged (" + std::to_string(scanned.damaged_bytes()) +
                             " bytes are not complete events; " + std::to_string(contents.records.size()) +
                             " events are); pass --allow-truncated to use the complete events");
  CollectorOptions co;
  co.keep_poses = options.keep_poses;
  LoadedLog log;
  log.path = path;
  log.truncated = truncated;
  log.damage = scanned.damage;
  log.collector = std::make_unique<MessageCollector>(co);
  for (const LogRecord& r : contents.records) log.collector->ingest(r.channel, r.data.data(), r.data.size(), path);
  log.collector->close_open_streams();
  if (log.collector->runs().empty())
    throw std::runtime_error(path + ": no ROBOZOO_RUN message in " + std::to_string(contents.records.size()) +
                             " events: not a robozoo-evolve log");
  return log;
}

std::string describe(const LoadedLog& log) {
  const CollectorStats& s = log.collector->stats();
  std::ostringstream o;
  o << log.path << ": " << log.collector->runs().size() << " run(s), " << s.messages << " messages";
  if (s.rejected() > 0) {
    o << "; skipped " << s.undecodable << " undecodable, " << s.inconsistent << " inconsistent, " << s.orphans
      << " orphaned";
    if (!s.problems.empty()) o << " (first: " << s.problems.front() << ")";
  }
  if (log.truncated) o << "; truncated";
  return o.str();
}

}  // namespace robozoo
