// robozoo-log: a log from the terminal, for people who script.
//   robozoo-log summary LOG [--json]                      channels, counts, runs, generations, champions, version
//   robozoo-log cat LOG [--channel C] [--generation G]    one JSON object per message (jq, pandas)
//   robozoo-log bus SENT RECORDED                         what a bus recording (lcm-logger) lost or changed
//   robozoo-log export LOG -o RUN.mcap                    the log as an MCAP file for Foxglove
//   robozoo-log cppn LOG [--genome N] [--format dot|svg]  a logged CPPN as a Graphviz drawing
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "util/run_program.hpp"
#include "evolve/core/version.hpp"
#include "evolve/io/log_compare.hpp"
#include "runlog/text/cppn_dot.hpp"
#include "runlog/text/log_cat.hpp"
#include "runlog/read/log_reader.hpp"
#include "runlog/read/log_stream.hpp"
#include "runlog/text/log_summary.hpp"
#include "runlog/text/logged_genome.hpp"
#include "runlog/export/mcap_export.hpp"
#include "util/parse_options.hpp"

namespace {

/// Writes `text` to `path` through PATH.partial; false (with `why`) on failure.
bool write_file(const std::string& path, const std::string& text, std::string& why) {
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    out << text;
    if (!out.flush()) {
      why = partial + ": cannot write";
      std::remove(partial.c_str());
      return false;
    }
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    why = path + ": cannot write";
    std::remove(partial.c_str());
    return false;
  }
  return true;
}

/// The SVG that Graphviz's dot draws from `dot_text`; throws std::runtime_error when dot fails.
std::string dot_to_svg(const std::string& dot_text, const std::string& scratch) {
  std::string why;
  const std::string in = scratch + ".dot", out = scratch + ".svg";
  if (!write_file(in, dot_text, why)) throw std::runtime_error(why);
  const robozoo::ProgramResult r = robozoo::run_program({"dot", "-Tsvg", in, "-o", out});
  std::remove(in.c_str());
  std::ifstream svg(out, std::ios::binary);
  std::stringstream text;
  text << svg.rdbuf();
  std::remove(out.c_str());
  if (r.status != 0)
    throw std::runtime_error("Graphviz's dot failed (status " + std::to_string(r.status) +
                             "): " + (r.status == 127 ? "not installed? (Debian package graphviz)" : r.output));
  return text.str();
}

}  // namespace

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
  CLI::App* bus =
      app.add_subcommand("bus",
                         "compare a recording of the bus (lcm-logger's) with the log of what was sent: events missing "
                         "(loss on the way), or changed, added, repeated or reordered (a defect). Exit 0 complete, 1 a "
                         "defect, 3 events missing");
  bus->add_option("SENT", log, "the log robozoo-evolve (or robozoo-replay play) wrote")->required();
  bus->add_option("RECORDED", recorded, "the recording of the bus")->required();
  bus->add_flag("--json", json, "the result as one JSON object");
  std::string output, compression = "zstd", format = "dot";
  size_t chunk_kib = 1024;
  CLI::App* exporter =
      app.add_subcommand("export",
                         "the log as an MCAP file for Foxglove: every message as JSON on its channel, poses as "
                         "foxglove.SceneUpdate on /robot/scene, generation figures on /generation/stats");
  exporter->add_option("LOG", log, "a log written by robozoo-evolve (or lcm-logger)")->required();
  exporter->add_option("-o,--output", output, "the MCAP file to write (written as FILE.partial, renamed at the end)")
      ->required();
  exporter->add_option("--compression", compression, "chunk compression")
      ->check(CLI::IsMember({"zstd", "lz4", "none"}))
      ->capture_default_str();
  exporter->add_option("--chunk-kib", chunk_kib, "close a chunk once its messages take this many KiB")
      ->check(CLI::Range(size_t{1}, size_t{1} << 20))
      ->capture_default_str();
  std::optional<int64_t> genome;
  CLI::App* cppn = app.add_subcommand("cppn", "a logged CPPN genome as a Graphviz drawing (DOT text or SVG)");
  cppn->add_option("LOG", log, "a log written by robozoo-evolve")->required();
  cppn->add_option("--genome", genome, "genome id (default: the champion of the log's last generation)");
  cppn->add_option("--format", format, "dot: Graphviz text; svg: drawn by Graphviz's dot")
      ->check(CLI::IsMember({"dot", "svg"}))
      ->capture_default_str();
  cppn->add_option("-o,--output", output, "write to this file (default: standard output)");
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-log")) return *stop;
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
      std::cout << nlohmann::json{{"sent", r.sent},
                                  {"received", r.received},
                                  {"missing", r.missing},
                                  {"defect", r.defect.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.defect)},
                                  {"exit_code", code}}
                       .dump()
                << "\n";
    else
      std::cout << "sent " << r.sent << " robozoo events, recorded " << r.received << ", missing " << r.missing
                << (r.defect.empty() ? std::string() : "; DEFECT: " + r.defect) << "\n";
    return code;
  }
  if (exporter->parsed()) {  // event by event: a log of any size in bounded memory
    ExportOptions options;
    options.writer.compression = mcap::parse_compression(compression);
    options.writer.chunk_bytes = chunk_kib * 1024;
    options.writer.library = "robozoo-log " + version_line();
    try {
      McapExporter mcap_out(output, options);
      const int64_t events = for_each_event(log, [&](const LogRecord& r) { mcap_out.add(r); });
      if (events == 0) throw std::runtime_error(log + ": no LCM events: not an LCM log");
      const ExportReport r = mcap_out.finish();
      int64_t total = 0;
      for (const auto& [topic, n] : r.messages) total += n;
      std::cerr << "robozoo-log: " << output << ": " << total << " messages on " << r.messages.size() << " topics in "
                << r.chunks << " chunks";
      if (r.skipped > 0) std::cerr << "; " << r.skipped << " events of other channels or undecodable, left out";
      if (r.poses_unshown > 0) std::cerr << "; " << r.poses_unshown << " poses without their morphology, no scene";
      std::cerr << "\n";
    } catch (const std::exception& e) {
      std::cerr << "robozoo-log: " << e.what() << ", not exported\n";
      return 1;
    }
    return 0;
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
  if (cppn->parsed()) {
    try {
      const cppn_genome_t g = find_logged_genome(scanned, genome);
      std::string text = cppn_to_dot(g);
      if (format == "svg")
        text = dot_to_svg(
            text, (std::filesystem::temp_directory_path() / ("robozoo-cppn-" + std::to_string(::getpid()))).string());
      if (output.empty()) {
        std::cout << text;
        std::cout.flush();
        return std::cout ? 0 : 1;
      }
      std::string why;
      if (!write_file(output, text, why)) throw std::runtime_error(why);
    } catch (const std::exception& e) {
      std::cerr << "robozoo-log: " << log << ": " << e.what() << "\n";
      return 1;
    }
    return 0;
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
  for (const LogDamage& d : scanned.damage)
    std::cerr << "robozoo-log: warning: " << log << ": " << d.describe() << "\n";
  cat_log(scanned, filter, std::cout);
  std::cout.flush();
  return std::cout ? 0 : 1;
}
