// robozoo-log: a log from the terminal, for people who script.
//   robozoo-log summary LOG [--json]                      channels, counts, runs, generations, champions, version
//   robozoo-log cat LOG [--channel C] [--generation G]    one JSON object per message (jq, pandas)
//   robozoo-log bus SENT RECORDED                         what a bus recording (lcm-logger) lost or changed
#include <CLI/CLI.hpp>

#include <iostream>

#include <nlohmann/json.hpp>

#include "evolve/core/version.hpp"
#include "evolve/io/log_compare.hpp"
#include "runlog/log_cat.hpp"
#include "runlog/log_reader.hpp"
#include "runlog/log_summary.hpp"

int main(int argc, char** argv) {
  using namespace robozoo;
  CLI::App app{"robozoo-log: what a robozoo log holds, for the terminal and for scripts."};
  app.set_version_flag("--version", robozoo::version_line());
  app.require_subcommand(1);
  std::string log;
  bool json = false;
  CatFilter filter;
  int32_t generation = -1;
  CLI::App* summary = app.add_subcommand("summary", "channels, message counts, runs, generations, champions, version");
  summary->add_option("LOG", log, "a log written by robozoo-evolve (or lcm-logger)")->required();
  summary->add_flag("--json", json, "the summary as one JSON object");
  CLI::App* cat = app.add_subcommand("cat", "one JSON object per message, one per line");
  cat->add_option("LOG", log, "a log written by robozoo-evolve (or lcm-logger)")->required();
  cat->add_option("--channel", filter.channel, "only this channel (ROBOZOO_POSE, or just pose)");
  cat->add_option("--generation", generation, "only the messages of this generation")->check(CLI::NonNegativeNumber);
  std::string recorded;
  CLI::App* bus = app.add_subcommand(
      "bus", "compare a recording of the bus (lcm-logger's) with the log of what was sent: events missing "
             "(loss on the way), or changed, added, repeated or reordered (a defect). Exit 0 complete, 1 a "
             "defect, 3 events missing");
  bus->add_option("SENT", log, "the log robozoo-evolve (or robozoo-replay play) wrote")->required();
  bus->add_option("RECORDED", recorded, "the recording of the bus")->required();
  bus->add_flag("--json", json, "the result as one JSON object");
  CLI11_PARSE(app, argc, argv);
  if (bus->parsed()) {
    LogContents sent, got;
    try {
      sent = scan_event_log(log).contents;
      got = scan_event_log(recorded).contents;
    } catch (const std::exception& e) {
      std::cerr << "robozoo-log: " << e.what() << "\n";
      return 2;
    }
    const BusRecording r = compare_bus_recording(sent, got);
    const int code = !r.defect.empty() ? 1 : r.missing > 0 ? 3 : 0;
    if (json)
      std::cout << nlohmann::json{{"sent", r.sent}, {"received", r.received}, {"missing", r.missing},
                                  {"defect", r.defect.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.defect)},
                                  {"exit_code", code}}
                       .dump()
                << "\n";
    else
      std::cout << "sent " << r.sent << " robozoo events, recorded " << r.received << ", missing " << r.missing
                << (r.defect.empty() ? std::string() : "; DEFECT: " + r.defect) << "\n";
    return code;
  }
  ScannedLog scanned;
  try {
    scanned = scan_event_log(log);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-log: " << e.what() << "\n";
    return 1;
  }
  if (scanned.contents.records.empty()) {
    std::cerr << "robozoo-log: " << log << ": no LCM events in " << scanned.contents.file_bytes
              << " bytes: not an LCM log\n";
    return 1;
  }
  if (summary->parsed()) {
    const LogSummary s = summarize_log(scanned, log);
    if (json)
      std::cout << to_json(s).dump(2) << "\n";
    else
      std::cout << format_summary(s);
    return s.runs.empty() ? 1 : 0;
  }
  if (generation >= 0) filter.generation = generation;
  for (const LogDamage& d : scanned.damage) std::cerr << "robozoo-log: warning: " << log << ": " << d.describe() << "\n";
  cat_log(scanned, filter, std::cout);
  std::cout.flush();
  return std::cout ? 0 : 1;
}
