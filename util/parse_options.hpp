#pragma once
// A program's command line parsed with CLI11, with the exit statuses robozoo's
// programs share (util/exit_status.hpp): --help and --version print and exit
// 0; a bad option or value is one line on stderr, "PROGRAM: what (see
// --help)", and exit status 2 (CLI11's own statuses, 105-109, differ by the
// kind of mistake). An argument the program does not know is named before a
// missing required one: CLI11 checks requirements first, so a mistyped option
// (--ouut for --out) would otherwise be reported as the option it misspells.
#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace robozoo {

/// The line that describes a parse error: CLI11's own, except for unknown
/// arguments, which are named in the order they were given (CLI11 2.1 lists
/// them backwards) and before a missing requirement.
inline std::string parse_error_message(const CLI::App& app, const CLI::ParseError& e) {
  const std::vector<std::string> unknown = app.get_allow_extras() ? std::vector<std::string>{} : app.remaining(true);
  // By type: CLI11 names some errors after the app rather than their kind.
  const bool about_arguments =
      dynamic_cast<const CLI::RequiredError*>(&e) != nullptr || dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr;
  if (unknown.empty() || !about_arguments) return e.what();
  std::string line =
      unknown.size() > 1 ? "The following arguments were not expected:" : "The following argument was not expected:";
  for (const std::string& arg : unknown) line += " " + arg;
  return line;
}

/// Parses `argv` into `app`. Returns nothing when the program goes on, else the
/// status to exit with. `quiet` prints nothing (an MPI rank other than the root).
inline std::optional<int> parse_options(CLI::App& app, int argc, const char* const* argv, const std::string& program,
                                        bool quiet = false) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help, --help-all and --version arrive as parse "errors" whose status is success.
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return quiet ? 0 : app.exit(e);
    if (!quiet) std::cerr << program << ": " << parse_error_message(app, e) << " (see --help)\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace robozoo
