#pragma once
// One-file replays: a champion of a log as ONE self-contained HTML file that
// plays it offline (file://, no server, no network) with the page's own
// drawing. The file holds the page (index.html with its style sheets and every
// module it imports, transitively), three.js (three.min.js plus a small module
// that re-exports its names) and the champion's frames, exactly those the
// server would send a page (view/state/frames.hpp), in
// <script type="application/json" id="robozoo-data">; page/offline.js finds
// them and feeds them to the page instead of the WebSocket.
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "runlog/read/run_record.hpp"
#include "view/serve/assets.hpp"

namespace robozoo::view {

struct ExportOptions {
  std::string log;                ///< a robozoo-evolve log
  std::optional<int64_t> genome;  ///< the genome to export (default: the log's last champion)
  bool allow_truncated = false;   ///< a log still being written: its complete events
  int resimulate_every = 4;       ///< a genome without logged poses is re-simulated keeping every k-th step (count)
};

/// The frames for one champion: hello (mode "file"), run, history (every
/// generation), champions (this one), robot, poses (all, done). Throws
/// std::runtime_error with one clear line for an unreadable or damaged log, a
/// log without champions, or an unknown genome.
nlohmann::json champion_frames(const ExportOptions& options);

/// The same frames for `genome` of `run` (it must have a morphology), from
/// wherever they came (a log, a compact result's replay); `source` names it
/// in the hello frame. std::runtime_error naming `source` when its trajectory
/// cannot be made.
nlohmann::json genome_frames(const RunRecord& run, const GenomeRecord& genome, const std::string& source,
                             int resimulate_every = 4);

/// The self-contained page for `frames` (an array of frames). Throws
/// std::runtime_error naming a page or three.js file it cannot read or inline.
std::string offline_page(const AssetDirs& dirs, const nlohmann::json& frames);

/// Writes `content` to `path` through `path`.partial and a rename: `path` is
/// either the whole file or untouched. Throws std::runtime_error naming the
/// path when it cannot be written (nothing is left behind).
void write_whole_file(const std::string& path, const std::string& content);

}  // namespace robozoo::view
