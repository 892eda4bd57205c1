#pragma once
// A program's command line parsed with CLI11, with the exit statuses robozoo's
// programs share (util/exit_status.hpp): --help and --version print and exit
// 0; a bad option or value is one line on stderr, "PROGRAM: what (see
// --help)", and exit status 2 (CLI11's own statuses, 105-109, differ by the
// kind of mistake).
#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>
#include <string>

namespace robozoo {

/// Parses `argv` into `app`. Returns nothing when the program goes on, else the
/// status to exit with. `quiet` prints nothing (an MPI rank other than the root).
inline std::optional<int> parse_options(CLI::App& app, int argc, const char* const* argv, const std::string& program,
                                        bool quiet = false) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help, --help-all and --version arrive as parse "errors" whose status is success.
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return quiet ? 0 : app.exit(e);
    if (!quiet) std::cerr << program << ": " << e.what() << " (see --help)\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace robozoo
