// Every relative link and image of every Markdown file in the repository names a file or
// folder that exists, and a link's #anchor into a Markdown file names one of its headings
// (GitHub's slugs): a clone has nothing else to explain it, so a file that moves must take
// its links along. Links in fenced code blocks and web addresses are left alone.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kSource = ROBOZOO_SOURCE_DIR;

// Folders that are not the repository's own text: builds, runs, installed packages.
bool skipped(const fs::path& dir) {
  const std::string name = dir.filename().string();
  return name == ".git" || name == "node_modules" || name == "runs" || name.rfind("build", 0) == 0;
}

std::vector<fs::path> markdown_files() {
  std::vector<fs::path> found;
  for (auto it = fs::recursive_directory_iterator(kSource); it != fs::recursive_directory_iterator(); ++it) {
    if (it->is_directory() && skipped(it->path())) {
      it.disable_recursion_pending();
    } else if (it->is_regular_file() && it->path().extension() == ".md") {
      found.push_back(it->path());
    }
  }
  return found;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The text outside ``` fences.
std::string without_code_blocks(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  bool fenced = false;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) {
      fenced = !fenced;
      continue;
    }
    if (!fenced) out += line + "\n";
  }
  return out;
}

// The targets of [text](target) and ![alt](target) that are not web addresses: "path" or
// "path#anchor" ("#anchor" alone: this file).
std::vector<std::string> file_links(const std::string& markdown) {
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  static const std::regex scheme("^[a-zA-Z][a-zA-Z0-9+.-]*:");
  std::vector<std::string> out;
  const std::string text = without_code_blocks(markdown);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
    std::string target = (*it)[1].str();
    if (target.empty() || std::regex_search(target, scheme)) continue;
    out.push_back(target);
  }
  return out;
}

// GitHub's anchor of a heading: lower case, spaces to '-', punctuation other than '-' and '_'
// dropped; a repeated heading gets -1, -2, ...
std::set<std::string> heading_anchors(const std::string& markdown) {
  std::set<std::string> anchors;
  std::istringstream in(without_code_blocks(markdown));
  std::string line;
  while (std::getline(in, line)) {
    const auto hashes = line.find_first_not_of('#');
    if (hashes == 0 || hashes == std::string::npos || hashes > 6 || line[hashes] != ' ') continue;
    std::string slug;
    for (const char c : line.substr(hashes + 1)) {
      const auto u = static_cast<unsigned char>(c);
      if (std::isalnum(u) || c == '-' || c == '_' || u >= 0x80) {
        slug += static_cast<char>(std::tolower(u));
      } else if (c == ' ') {
        slug += '-';
      }
    }
    while (!slug.empty() && slug.front() == '-') slug.erase(slug.begin());
    while (!slug.empty() && slug.back() == '-') slug.pop_back();
    std::string unique = slug;
    for (int n = 1; anchors.count(unique) != 0; ++n) unique = slug + "-" + std::to_string(n);
    anchors.insert(unique);
  }
  return anchors;
}

}  // namespace

TEST(DocsLinks, TheLinkReaderFindsFileLinksOnly) {
  const std::string md =
      "See [a](docs/a.md), ![p](media/p.png) and [b](b.md#part).\n"
      "[web](https://example.org/x) [here](#top) [mail](mailto:x@y)\n"
      "```sh\n[not](in/code.md)\n```\n"
      "  ```\n[nor](indented/fence.md)\n  ```\n"
      "[after](c/)\n";
  EXPECT_EQ(file_links(md), (std::vector<std::string>{"docs/a.md", "media/p.png", "b.md#part", "#top", "c/"}));
}

TEST(DocsLinks, HeadingAnchorsAreGitHubs) {
  const std::string md =
      "# robozoo\n## Physics defaults: the measurements behind them\n### Film and check a best-of-run robot\n"
      "## Building\n## Building\n```sh\n# not a heading\n```\n#nospace\n####### seven\n## `robozoo-stats` (M2)\n";
  EXPECT_EQ(heading_anchors(md), (std::set<std::string>{"robozoo", "physics-defaults-the-measurements-behind-them",
                                                        "film-and-check-a-best-of-run-robot", "building", "building-1",
                                                        "robozoo-stats-m2"}));
}

TEST(DocsLinks, EveryRelativeLinkNamesAFileThatExists) {
  const auto files = markdown_files();
  ASSERT_GE(files.size(), 20u) << "the repository's Markdown files were not found under " << kSource;
  size_t links = 0;
  for (const auto& file : files) {
    const std::string from = fs::relative(file, kSource).string();
    for (const auto& target : file_links(read(file))) {
      ++links;
      const auto hash = target.find('#');
      const std::string path = target.substr(0, hash);
      const fs::path resolved = path.empty() ? file : (file.parent_path() / path).lexically_normal();
      if (!fs::exists(resolved)) {
        ADD_FAILURE() << from << " links to " << target << ", which does not exist";
      } else if (hash != std::string::npos && resolved.extension() == ".md") {
        const std::string anchor = target.substr(hash + 1);
        EXPECT_EQ(heading_anchors(read(resolved)).count(anchor), 1u)
            << from << " links to " << target << ": " << resolved.filename().string() << " has no heading #" << anchor;
      }
    }
  }
  EXPECT_GE(links, 50u) << "too few links found: the reader is broken";
}
