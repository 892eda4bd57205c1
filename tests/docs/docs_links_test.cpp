// Every relative link and image of every Markdown file in the repository names a file or
// folder that exists: a clone has nothing else to explain it, so a file that moves must
// take its links along. Links in fenced code blocks, web addresses and in-page anchors
// are not files and are left alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
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

// The targets of [text](target) and ![alt](target) that name a file: no scheme, no anchor only.
std::vector<std::string> file_links(const std::string& markdown) {
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  static const std::regex scheme("^[a-zA-Z][a-zA-Z0-9+.-]*:");
  std::vector<std::string> out;
  const std::string text = without_code_blocks(markdown);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
    std::string target = (*it)[1].str();
    if (target.empty() || target[0] == '#' || std::regex_search(target, scheme)) continue;
    out.push_back(target.substr(0, target.find('#')));
  }
  return out;
}

}  // namespace

TEST(DocsLinks, TheLinkReaderFindsFileLinksOnly) {
  const std::string md =
      "See [a](docs/a.md), ![p](media/p.png) and [b](b.md#part).\n"
      "[web](https://example.org/x) [here](#top) [mail](mailto:x@y)\n"
      "```sh\n[not](in/code.md)\n```\n"
      "  ```\n[nor](indented/fence.md)\n  ```\n"
      "[after](c/)\n";
  EXPECT_EQ(file_links(md), (std::vector<std::string>{"docs/a.md", "media/p.png", "b.md", "c/"}));
}

TEST(DocsLinks, EveryRelativeLinkNamesAFileThatExists) {
  const auto files = markdown_files();
  ASSERT_GE(files.size(), 20u) << "the repository's Markdown files were not found under " << kSource;
  size_t links = 0;
  for (const auto& file : files) {
    for (const auto& target : file_links(read(file))) {
      ++links;
      const fs::path resolved = (file.parent_path() / target).lexically_normal();
      EXPECT_TRUE(fs::exists(resolved)) << fs::relative(file, kSource).string() << " links to " << target
                                        << ", which does not exist";
    }
  }
  EXPECT_GE(links, 50u) << "too few links found: the reader is broken";
}
