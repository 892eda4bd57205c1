#include "evolve/io/log_compare.hpp"

#include "evolve/messages/build.hpp"

namespace robozoo {

namespace {
template <class T>
bool renormalize(const std::vector<uint8_t>& data, std::vector<uint8_t>& out, void (*clear)(T&)) {
  T m{};
  int used = -1;
  try {
    used = m.decode(data.data(), 0, static_cast<int>(data.size()));
  } catch (const std::exception&) {
    return false;
  }
  if (used != static_cast<int>(data.size())) return false;
  clear(m);
  out = encode_message(m);
  return true;
}
}  // namespace

bool normalize_message(const std::string& channel, const std::vector<uint8_t>& data, std::vector<uint8_t>& out) {
  if (channel == kChannelRun) return renormalize<run_t>(data, out, [](run_t& m) { m.utime = 0; });
  if (channel == kChannelGeneration)
    return renormalize<generation_t>(data, out, [](generation_t& m) {
      m.utime = 0;
      m.eval_seconds = 0;
      m.generation_seconds = 0;
    });
  if (channel == kChannelGenome) return renormalize<cppn_genome_t>(data, out, [](cppn_genome_t& m) { m.utime = 0; });
  if (channel == kChannelMorphology)
    return renormalize<morphology_t>(data, out, [](morphology_t& m) { m.utime = 0; });
  if (channel == kChannelPose) return renormalize<pose_t>(data, out, [](pose_t& m) { m.utime = 0; });
  return false;
}

std::string first_log_difference(const LogContents& a, const LogContents& b) {
  auto robozoo_events = [](const LogContents& log) {
    std::vector<std::pair<std::string, std::vector<uint8_t>>> out;
    for (const auto& r : log.records) {
      std::vector<uint8_t> norm;
      if (r.channel.rfind("ROBOZOO_", 0) != 0) continue;
      if (!normalize_message(r.channel, r.data, norm)) norm = {0xde, 0xad};  // undecodable: compare as such
      out.emplace_back(r.channel, std::move(norm));
    }
    return out;
  };
  const auto ea = robozoo_events(a), eb = robozoo_events(b);
  const size_t n = std::min(ea.size(), eb.size());
  for (size_t i = 0; i < n; ++i) {
    if (ea[i].first != eb[i].first)
      return "event " + std::to_string(i) + ": channel " + ea[i].first + " vs " + eb[i].first;
    if (ea[i].second != eb[i].second)
      return "event " + std::to_string(i) + " (" + ea[i].first + "): contents differ";
  }
  if (ea.size() != eb.size())
    return "robozoo events: " + std::to_string(ea.size()) + " vs " + std::to_string(eb.size());
  return "";
}

}  // namespace robozoo
