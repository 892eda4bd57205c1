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
  const Parsed bad = parse({"--count", "11"});
  ASSERT_TRUE(bad.stop.has_value());
  EXPECT_EQ(*bad.stop, 2);
  EXPECT_EQ(bad.err.rfind("prog: --count: ", 0), 0u) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
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
