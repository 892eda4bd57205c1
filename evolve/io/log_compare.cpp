#include "evolve/io/log_compare.hpp"

#include <algorithm>

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"

namespace robozoo {

namespace {
template <class T, class Clear>
bool renormalize(const std::vector<uint8_t>& data, std::vector<uint8_t>& out, std::string* why, Clear clear) {
  T m{};
  if (!safe_decode(data.data(), data.size(), m, why)) return false;
  clear(m);
  out = encode_message(m);
  return true;
}

// One robozoo event as compared.
struct Event {
  const LogRecord* record = nullptr;
  std::vector<uint8_t> norm;  ///< normalised bytes (raw bytes for an unknown ROBOZOO_ channel)
  bool decoded = true;        ///< false: does not decode; equals nothing
  std::string why;            ///< why it does not decode
};

std::vector<Event> robozoo_events(const LogContents& log) {
  std::vector<Event> out;
  for (const auto& r : log.records) {
    if (r.channel.rfind("ROBOZOO_", 0) != 0 || r.channel == kChannelBus) continue;
    Event e;
    e.record = &r;
    if (!is_known_channel(r.channel))
      e.norm = r.data;
    else
      e.decoded = normalize_message(r.channel, r.data, e.norm, &e.why);
    out.push_back(std::move(e));
  }
  return out;
}

std::string hex_byte(uint8_t b) {
  const char* digits = "0123456789abcdef";
  return std::string("0x") + digits[b >> 4] + digits[b & 15];
}
}  // namespace

bool is_known_channel(const std::string& channel) {
  return channel == kChannelRun || channel == kChannelGeneration || channel == kChannelGenome ||
         channel == kChannelMorphology || channel == kChannelPose;
}

bool normalize_message(const std::string& channel, const std::vector<uint8_t>& data, std::vector<uint8_t>& out,
                       std::string* why) {
  if (channel == kChannelRun) return renormalize<run_t>(data, out, why, [](run_t& m) { m.utime = 0; });
  if (channel == kChannelGeneration)
    return renormalize<generation_t>(data, out, why, [](generation_t& m) {
      m.utime = 0;
      m.eval_seconds = 0;
      m.generation_seconds = 0;
    });
  if (channel == kChannelGenome)
    return renormalize<cppn_genome_t>(data, out, why, [](cppn_genome_t& m) { m.utime = 0; });
  if (channel == kChannelMorphology)
    return renormalize<morphology_t>(data, out, why, [](morphology_t& m) { m.utime = 0; });
  if (channel == kChannelPose) return renormalize<pose_t>(data, out, why, [](pose_t& m) { m.utime = 0; });
  if (why) *why = "not a robozoo channel";
  return false;
}

std::string first_log_difference(const LogContents& a, const LogContents& b) {
  const auto ea = robozoo_events(a), eb = robozoo_events(b);
  const size_t n = std::min(ea.size(), eb.size());
  for (size_t i = 0; i < n; ++i) {
    const Event& x = ea[i];
    const Event& y = eb[i];
    const std::string where = "event " + std::to_string(i) + " (event number " + std::to_string(x.record->eventnum) +
                              " vs " + std::to_string(y.record->eventnum) + ")";
    if (x.record->channel != y.record->channel)
      return where + ": channel " + x.record->channel + " vs " + y.record->channel;
    const std::string& ch = x.record->channel;
    if (!x.decoded) return where + " (" + ch + "): the first log's message does not decode: " + x.why;
    if (!y.decoded) return where + " (" + ch + "): the second log's message does not decode: " + y.why;
    if (x.norm != y.norm) {
      size_t k = 0;
      while (k < x.norm.size() && k < y.norm.size() && x.norm[k] == y.norm[k]) ++k;
      std::string at = "byte " + std::to_string(k) + " of the normalised message: ";
      at += k < x.norm.size() ? hex_byte(x.norm[k]) : std::string("end");
      at += " vs ";
      at += k < y.norm.size() ? hex_byte(y.norm[k]) : std::string("end");
      return where + " (" + ch + "): contents differ at " + at + " (" + std::to_string(x.norm.size()) + " vs " +
             std::to_string(y.norm.size()) + " bytes)";
    }
  }
  if (ea.size() != eb.size()) {
    const auto& longer = ea.size() > eb.size() ? ea : eb;
    return "robozoo events: " + std::to_string(ea.size()) + " vs " + std::to_string(eb.size()) + "; the " +
           (ea.size() > eb.size() ? "first" : "second") + " log goes on with " + longer[n].record->channel +
           " (event number " + std::to_string(longer[n].record->eventnum) + ")";
  }
  return "";
}

BusRecording compare_bus_recording(const LogContents& sent, const LogContents& received) {
  BusRecording out;
  const auto es = robozoo_events(sent), er = robozoo_events(received);
  out.sent = es.size();
  out.received = er.size();
  size_t j = 0;  // next candidate in `sent`
  for (size_t i = 0; i < er.size(); ++i) {
    const Event& y = er[i];
    if (!y.decoded && is_known_channel(y.record->channel)) {
      out.defect = "received event " + std::to_string(i) + " (event number " + std::to_string(y.record->eventnum) +
                   ", " + y.record->channel + ") does not decode: " + y.why;
      return out;
    }
    size_t k = j;
    while (k < es.size() && !(es[k].decoded && es[k].record->channel == y.record->channel && es[k].norm == y.norm)) ++k;
    if (k == es.size()) {
      // Equal to nothing later in what was sent: changed, extra or out of order.
      bool earlier = false;
      for (size_t m = 0; m < j && !earlier; ++m)
        earlier = es[m].decoded && es[m].record->channel == y.record->channel && es[m].norm == y.norm;
      out.defect = "received event " + std::to_string(i) + " (event number " + std::to_string(y.record->eventnum) +
                   ", " + y.record->channel + ") " +
                   (earlier ? "repeats or reorders an earlier sent event"
                            : "equals no event that was sent after " + std::to_string(j) + " events");
      return out;
    }
    out.missing += k - j;
    j = k + 1;
  }
  out.missing += es.size() - j;
  return out;
}

}  // namespace robozoo
