#include "runlog/text/log_cat.hpp"

#include <algorithm>
#include <cctype>

#include "runlog/text/message_json.hpp"

namespace robozoo {

std::string channel_name(const std::string& value) {
  std::string upper = value;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  for (const char* robozoo : {"RUN", "GENERATION", "GENOME", "MORPHOLOGY", "POSE"})
    if (upper == robozoo) return "ROBOZOO_" + upper;
  return value;
}

int64_t cat_log(const ScannedLog& log, const CatFilter& filter, std::ostream& out) {
  const std::string channel = filter.channel.empty() ? "" : channel_name(filter.channel);
  int64_t written = 0;
  for (const LogRecord& r : log.contents.records) {
    if (!channel.empty() && r.channel != channel) continue;
    nlohmann::json line = {{"event", r.eventnum}, {"timestamp", r.timestamp}, {"channel", r.channel}};
    nlohmann::json message;
    std::string why;
    const bool ok = message_to_json(r.channel, r.data.data(), r.data.size(), message, why);
    if (filter.generation) {
      if (!ok || !message.contains("generation") || message["generation"] != *filter.generation) continue;
    }
    if (ok)
      line["message"] = std::move(message);
    else if (!why.empty())
      line["error"] = why;
    else
      line["bytes"] = r.data.size();
    out << line.dump() << '\n';
    ++written;
  }
  return written;
}

}  // namespace robozoo
