// parse_options: the statuses robozoo's programs share for their command line.
#include "util/parse_options.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace robozoo {
namespace {

struct Parsed {
  std::optional<int> stop;
  std::string out, err;
  int count = 0;
};

Parsed parse(std::vector<const char*> args, bool quiet = false) {
  CLI::App app{"a test program"};
  int count = 0;
  app.add_option("--count", count, "a number")->check(CLI::Range(1, 10));
  app.set_version_flag("--version", "test 1.0");
  args.insert(args.begin(), "prog");
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  Parsed p;
  p.stop = parse_options(app, static_cast<int>(args.size()), args.data(), "prog", quiet);
  p.out = ::testing::internal::GetCapturedStdout();
  p.err = ::testing::internal::GetCapturedStderr();
  p.count = count;
  return p;
}

TEST(ParseOptions, GoodOptionsGoOn) {
  const Parsed p = parse({"--count", "3"});
  EXPECT_FALSE(p.stop.has_value());
  EXPECT_EQ(p.count, 3);
  EXPECT_EQ(p.err, "");
}

TEST(ParseOptions, HelpAndVersionPrintAndExitZero) {
  const Parsed help = parse({"--help"});
  ASSERT_TRUE(help.stop.has_value());
  EXPECT_EQ(*help.stop, 0);
  EXPECT_NE(help.out.find("--count"), std::string::npos) << help.out;
  const Parsed version = parse({"--version"});
  ASSERT_TRUE(version.stop.has_value());
  EXPECT_EQ(*version.stop, 0);
  EXPECT_NE(version.out.find("test 1.0"), std::string::npos) << version.out;
}

TEST(ParseOptions, AnUnknownOptionOrABadValueIsOneLineAndStatusTwo) {
  const Parsed unknown = parse({"--bogus"});
  ASSERT_TRUE(unknown.stop.has_value());
  EXPECT_EQ(*unknown.stop, 2);
  EXPECT_EQ(unknown.err, "prog: The following argument was not expected: --bogus (see --help)\n");
  const Parsed two = parse({"--aa", "--count", "3", "--bb"});
  EXPECT_EQ(two.stop, std::optional<int>(2));
  EXPECT_EQ(two.err, "prog: The following arguments were not expected: --aa --bb (see --help)\n");
  const Parsed bad = parse({"--count", "11"});
  ASSERT_TRUE(bad.stop.has_value());
  EXPECT_EQ(*bad.stop, 2);
  EXPECT_EQ(bad.err.rfind("prog: --count: ", 0), 0u) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
}

// A program with a required option and a subcommand, as robozoo-experiment and
// robozoo-render are.
Parsed parse_with_requirements(std::vector<const char*> args, bool subcommand) {
  CLI::App app{"a test program"};
  std::string out;
  if (subcommand) {
    app.require_subcommand(1);
    app.add_subcommand("zoo", "a subcommand")->add_option("--out", out, "a folder")->required();
  } else {
    app.add_option("--out", out, "a folder")->required();
  }
  args.insert(args.begin(), "prog");
  ::testing::internal::CaptureStderr();
  Parsed p;
  p.stop = parse_options(app, static_cast<int>(args.size()), args.data(), "prog");
  p.err = ::testing::internal::GetCapturedStderr();
  return p;
}

TEST(ParseOptions, AnUnknownArgumentIsNamedBeforeAMissingRequiredOne) {
  // A mistyped option: CLI11 alone would say "--out is required". The arguments
  // come in the order they were given.
  const Parsed typo = parse_with_requirements({"--ouut", "runs"}, false);
  EXPECT_EQ(typo.stop, std::optional<int>(2));
  EXPECT_EQ(typo.err, "prog: The following arguments were not expected: --ouut runs (see --help)\n");
  // A mistyped subcommand, and an unknown option inside the right one.
  const Parsed sub = parse_with_requirements({"zooo"}, true);
  EXPECT_EQ(sub.err, "prog: The following argument was not expected: zooo (see --help)\n");
  const Parsed inside = parse_with_requirements({"zoo", "--bogus"}, true);
  EXPECT_EQ(inside.err, "prog: The following argument was not expected: --bogus (see --help)\n");
  // Nothing unknown: the missing requirement itself.
  EXPECT_EQ(parse_with_requirements({}, false).err, "prog: --out is required (see --help)\n");
  EXPECT_EQ(parse_with_requirements({"zoo"}, true).err, "prog: --out is required (see --help)\n");
}

TEST(ParseOptions, QuietPrintsNothingAndKeepsTheStatuses) {
  const Parsed unknown = parse({"--bogus"}, true);
  EXPECT_EQ(unknown.stop, std::optional<int>(2));
  const Parsed help = parse({"--help"}, true);
  EXPECT_EQ(help.stop, std::optional<int>(0));
  EXPECT_EQ(unknown.err + unknown.out + help.err + help.out, "");
}

}  // namespace
}  // namespace robozoo
