#include "view/serve/assets.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "util/program_path.hpp"

namespace robozoo::view {

namespace {

struct Entry {
  const char* url;
  bool three;        ///< from three.js's folder, else the page's
  const char* file;  ///< relative to that folder
  const char* type;
};

// The whole set of served files.
constexpr Entry kEntries[] = {
    {"/", false, "index.html", "text/html; charset=utf-8"},
    {"/index.html", false, "index.html", "text/html; charset=utf-8"},
    {"/style.css", false, "style.css", "text/css; charset=utf-8"},
    {"/view.js", false, "view.js", "text/javascript; charset=utf-8"},
    {"/scene.js", false, "scene.js", "text/javascript; charset=utf-8"},
    {"/chart.js", false, "chart.js", "text/javascript; charset=utf-8"},
    {"/strip.js", false, "strip.js", "text/javascript; charset=utf-8"},
    {"/playback.js", false, "playback.js", "text/javascript; charset=utf-8"},
    {"/timeline.js", false, "timeline.js", "text/javascript; charset=utf-8"},
    {"/cppn.js", false, "cppn.js", "text/javascript; charset=utf-8"},
    {"/offline.js", false, "offline.js", "text/javascript; charset=utf-8"},
    {"/ticks.js", false, "ticks.js", "text/javascript; charset=utf-8"},
    {"/experiment.html", false, "experiment.html", "text/html; charset=utf-8"},
    {"/experiment.js", false, "experiment.js", "text/javascript; charset=utf-8"},
    // OrbitControls imports "../../../build/three.module.js": the same layout as the install.
    {"/three/build/three.module.js", true, "build/three.module.js", "text/javascript; charset=utf-8"},
    {"/three/examples/jsm/controls/OrbitControls.js", true, "examples/jsm/controls/OrbitControls.js",
     "text/javascript; charset=utf-8"},
};

std::string read_whole(const std::string& path, const std::string& hint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("robozoo-view needs " + path + " (" + hint + ")");
  std::ostringstream s;
  s << in.rdbuf();
  if (!in.good() && !in.eof()) throw std::runtime_error("cannot read " + path);
  return s.str();
}

}  // namespace

AssetDirs default_asset_dirs() {
  AssetDirs d;
  d.page = program_dir() + "/../share/robozoo/view";
  d.three = ROBOZOO_THREE_DIR;
  return d;
}

AssetTable AssetTable::load(const AssetDirs& dirs) {
  AssetTable t;
  for (const Entry& e : kEntries) {
    const std::string path = (e.three ? dirs.three : dirs.page) + "/" + e.file;
    const std::string hint = e.three ? "Debian package libjs-three, or --three-dir"
                                     : "the page installed beside robozoo-view, or --page-dir";
    t.assets_[e.url] = Asset{e.type, read_whole(path, hint)};
  }
  return t;
}

const Asset* AssetTable::find(const std::string& target) const {
  const std::string path = target.substr(0, target.find_first_of("?#"));
  const auto it = assets_.find(path);
  return it == assets_.end() ? nullptr : &it->second;
}

}  // namespace robozoo::view
