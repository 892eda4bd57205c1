#include "view/replays/export.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "runlog/read/log_source.hpp"
#include "runlog/robots/selection.hpp"
#include "runlog/robots/trajectory.hpp"
#include "view/state/frames.hpp"

namespace robozoo::view {

namespace {

std::string read_text(const std::string& path, const std::string& hint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path + " (" + hint + ")");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string base64(const std::string& in) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const uint32_t v = (uint8_t(in[i]) << 16) | (uint8_t(in[i + 1]) << 8) | uint8_t(in[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out.push_back(k[(v >> s) & 63]);
  }
  if (i < in.size()) {
    const bool two = i + 1 < in.size();
    const uint32_t v = (uint8_t(in[i]) << 16) | (two ? uint8_t(in[i + 1]) << 8 : 0);
    out.push_back(k[(v >> 18) & 63]);
    out.push_back(k[(v >> 12) & 63]);
    out.push_back(two ? k[(v >> 6) & 63] : '=');
    out.push_back('=');
  }
  return out;
}

std::string data_url(const std::string& js) { return "data:text/javascript;base64," + base64(js); }

/// The page's URL path of `spec` imported by the module at `from` ("/x/y.js").
std::string resolve(const std::string& from, const std::string& spec) {
  if (spec[0] == '/') return spec;
  std::vector<std::string> parts;
  std::istringstream dir(from.substr(0, from.rfind('/')));
  for (std::string p; std::getline(dir, p, '/');)
    if (!p.empty()) parts.push_back(p);
  std::istringstream rel(spec);
  for (std::string p; std::getline(rel, p, '/');) {
    if (p == "..") {
      if (parts.empty()) throw std::runtime_error(from + " imports " + spec + ": outside the page");
      parts.pop_back();
    } else if (p != "." && !p.empty()) {
      parts.push_back(p);
    }
  }
  std::string out;
  for (const std::string& p : parts) out += "/" + p;
  return out;
}

constexpr const char* kThreeModule = "/three/build/three.module.js";

/// Gathers the page's modules (URL path -> source with its imports made bare
/// "rz/..." names) from the entry points, transitively.
class ModuleSet {
 public:
  explicit ModuleSet(const AssetDirs& dirs) : dirs_(dirs) {}

  void add(const std::string& url) {
    if (url == kThreeModule || modules_.count(url)) return;
    if (url.find("..") != std::string::npos) throw std::runtime_error("cannot inline " + url);
    const bool three = url.rfind("/three/", 0) == 0;
    const std::string file = three ? dirs_.three + url.substr(6) : dirs_.page + url;
    std::string src =
        read_text(file, three ? "Debian package libjs-three, or --three-dir" : "the page's folder, or --page-dir");
    modules_[url] = "";  // taken, against cycles
    // import ... from "x" / import "x" / import("x"): the specifier as a bare name.
    static const std::regex spec_re(R"re(((?:\bfrom|\bimport)\s*\(?\s*)(["'])([^"'\n]+)\2)re");
    std::string out;
    std::vector<std::string> deps;
    auto it = std::sregex_iterator(src.begin(), src.end(), spec_re);
    size_t last = 0;
    for (; it != std::sregex_iterator(); ++it) {
      const std::smatch& m = *it;
      const std::string spec = m[3].str();
      std::string bare = spec;
      if (spec[0] == '/' || spec.rfind("./", 0) == 0 || spec.rfind("../", 0) == 0) {
        const std::string target = resolve(url, spec);
        bare = target == kThreeModule ? "three" : "rz" + target;
        if (target != kThreeModule) deps.push_back(target);
      } else if (spec != "three") {
        throw std::runtime_error(url + " imports " + spec + ": not a file of the page");
      }
      out += src.substr(last, m.position(0) - last) + m[1].str() + "\"" + bare + "\"";
      last = m.position(0) + m.length(0);
    }
    out += src.substr(last);
    modules_[url] = out;
    for (const std::string& d : deps) add(d);
  }

  /// The import map: "three" and every module as a data: URL.
  nlohmann::json import_map(const std::string& three_shim) const {
    nlohmann::json imports = {{"three", data_url(three_shim)}};
    for (const auto& [url, src] : modules_) imports["rz" + url] = data_url(src);
    return {{"imports", imports}};
  }

 private:
  const AssetDirs& dirs_;
  std::map<std::string, std::string> modules_;
};

/// three.min.js defines the global THREE; the module "three" re-exports the
/// names three.module.js exports (its closing export list), from that global.
std::string three_shim(const AssetDirs& dirs) {
  const std::string module =
      read_text(dirs.three + "/build/three.module.js", "Debian package libjs-three, or --three-dir");
  const size_t at = module.rfind("export {");
  const size_t end = module.find('}', at);
  if (at == std::string::npos || end == std::string::npos)
    throw std::runtime_error(dirs.three + "/build/three.module.js: no export list to re-export");
  std::string shim = "const T = globalThis.THREE;\n";
  std::istringstream names(module.substr(at + 8, end - at - 8));
  static const std::regex name_re(R"(\s*(\w+)(?:\s+as\s+(\w+))?\s*)");
  for (std::string item; std::getline(names, item, ',');) {
    std::smatch m;
    if (!std::regex_match(item, m, name_re)) throw std::runtime_error("three.module.js: cannot read export " + item);
    const std::string name = m[2].matched ? m[2].str() : m[1].str();
    shim += "export const " + name + " = T." + name + ";\n";
  }
  return shim;
}

/// Text safe inside a <script> element (no "</script", no "<!--").
std::string script_safe(const std::string& text, const std::string& what) {
  if (text.find("</script") != std::string::npos || text.find("<!--") != std::string::npos)
    throw std::runtime_error(what + " cannot be inlined in a <script> element");
  return text;
}

}  // namespace

nlohmann::json champion_frames(const ExportOptions& o) {
  LoadOptions lo;
  lo.allow_truncated = o.allow_truncated;
  const LoadedLog log = load_log(o.log, lo);  // throws naming the path: missing, damaged, no run
  const std::vector<const RunRecord*> runs = log.runs();
  const RunRecord* run = nullptr;
  const GenomeRecord* genome = nullptr;
  if (o.genome) {
    for (const RunRecord* r : runs)
      if (const GenomeRecord* g = r->find(*o.genome)) run = r, genome = g;
    if (!genome) throw std::runtime_error(o.log + ": no genome " + std::to_string(*o.genome));
    if (!genome->has_morphology)
      throw std::runtime_error(o.log + ": genome " + std::to_string(*o.genome) + " has no logged morphology");
  } else {
    for (const RunRecord* r : runs) {
      const std::vector<Pick> c = champions(*r);
      if (!c.empty()) run = r, genome = c.back().genome;
    }
    if (!genome) throw std::runtime_error(o.log + ": no champion with a morphology");
  }
  return genome_frames(*run, *genome, o.log.substr(o.log.find_last_of('/') + 1), o.resimulate_every);
}

nlohmann::json genome_frames(const RunRecord& run, const GenomeRecord& genome, const std::string& source,
                             int resimulate_every) {
  Trajectory t;
  try {
    t = genome_trajectory(run, genome, false, resimulate_every);
  } catch (const std::exception& e) {
    throw std::runtime_error(source + ": genome " + std::to_string(genome.genome.genome_id) + ": " + e.what());
  }
  const Eigen::Vector3d target = run_target(run.run);
  const double target3[3] = {target.x(), target.y(), target.z()};
  nlohmann::json gens = nlohmann::json::array();
  for (const generation_t& g : run.generations) gens.push_back(generation_json(g));
  nlohmann::json champion = champion_json(genome.genome);
  champion.erase("t");
  return nlohmann::json::array({hello_json("file", source),
                                run_json(run.run, target3),
                                {{"t", "history"}, {"gens", gens}},
                                {{"t", "champions"}, {"list", nlohmann::json::array({champion})}},
                                robot_json(genome.genome, genome.morphology, false, false),
                                trajectory_json(genome.genome.genome_id, t)});
}

std::string offline_page(const AssetDirs& dirs, const nlohmann::json& frames) {
  std::string html = read_text(dirs.page + "/index.html", "the page's folder, or --page-dir");
  // The server's import map goes; ours comes where it was.
  static const std::regex importmap_re(R"re(<script type="importmap">[\s\S]*?</script>\s*)re");
  std::smatch m;
  if (!std::regex_search(html, m, importmap_re)) throw std::runtime_error(dirs.page + "/index.html: no import map");
  const std::string marker = "<!-- robozoo-view: three.js, import map, data -->\n";
  html.replace(static_cast<size_t>(m.position(0)), static_cast<size_t>(m.length(0)), marker);
  ModuleSet modules(dirs);
  // Module entry points: <script type="module" src="/x.js"></script> -> an inline import.
  static const std::regex entry_re(R"re(<script type="module" src="(/[^"]+)"></script>)re");
  std::string out;
  size_t last = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), entry_re); it != std::sregex_iterator(); ++it) {
    modules.add((*it)[1].str());
    out += html.substr(last, it->position(0) - last) + "<script type=\"module\">import \"rz" + (*it)[1].str() +
           "\";</script>";
    last = it->position(0) + it->length(0);
  }
  html = out + html.substr(last);
  // Style sheets inline.
  static const std::regex css_re(R"re(<link rel="stylesheet" href="(/[^"]+)">)re");
  out.clear();
  last = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), css_re); it != std::sregex_iterator(); ++it) {
    const std::string css = read_text(dirs.page + (*it)[1].str(), "the page's folder, or --page-dir");
    if (css.find("</style") != std::string::npos) throw std::runtime_error((*it)[1].str() + " cannot be inlined");
    out += html.substr(last, it->position(0) - last) + "<style>\n" + css + "</style>";
    last = it->position(0) + it->length(0);
  }
  html = out + html.substr(last);
  // JSON text is safe in a script element once every '<' (only ever inside a string) is escaped.
  std::string data;
  for (char c : frames.dump()) data += c == '<' ? std::string("\\u003c") : std::string(1, c);
  const std::string three = script_safe(
      read_text(dirs.three + "/three.min.js", "Debian package libjs-three, or --three-dir"), "three.min.js");
  const std::string head = "<script>\n" + three + "\n</script>\n<script type=\"importmap\">\n" +
                           modules.import_map(three_shim(dirs)).dump() +
                           "\n</script>\n<script type=\"application/json\" id=\"robozoo-data\">" + data + "</script>\n";
  // At the old import map's place (in <head>, before the page's first module script).
  return html.replace(html.find(marker), marker.size(), head);
}

void write_whole_file(const std::string& path, const std::string& content) {
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + path);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) {
      std::remove(partial.c_str());
      throw std::runtime_error("cannot write " + path + " (disk full?)");
    }
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    std::remove(partial.c_str());
    throw std::runtime_error("cannot write " + path + " (rename failed)");
  }
}

}  // namespace robozoo::view
