#pragma once
// The files robozoo-view serves: a fixed table of URL paths, each read into
// memory once at start-up from the page's folder (installed beside the
// program) or from three.js's Debian install (libjs-three). No part of a URL
// ever reaches the file system: a path not in the table is a 404.
#include <map>
#include <string>

namespace robozoo::view {

struct Asset {
  std::string content_type;
  std::string body;
};

/// Where the files come from.
struct AssetDirs {
  std::string page;   ///< index.html, view.js, ... (default: <program dir>/../share/robozoo/view)
  std::string three;  ///< three.js's install: build/three.module.js, examples/jsm/controls/OrbitControls.js
};

/// The default folders: the page beside the program, three.js where Debian puts it.
AssetDirs default_asset_dirs();

class AssetTable {
 public:
  /// Reads every file; throws std::runtime_error naming a missing file and the
  /// package or option that provides it.
  static AssetTable load(const AssetDirs& dirs);
  /// The asset for a request target ("/view.js?x" is "/view.js"); nullptr if none.
  const Asset* find(const std::string& target) const;
  size_t size() const { return assets_.size(); }

 private:
  std::map<std::string, Asset> assets_;
};

}  // namespace robozoo::view
