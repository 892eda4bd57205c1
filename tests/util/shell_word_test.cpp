#include "util/shell_word.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace {

using robozoo::shell_word;

TEST(ShellWord, LeavesPlainWordsAlone) {
  EXPECT_EQ(shell_word("media/experiment/paper/m3"), "media/experiment/paper/m3");
  EXPECT_EQ(shell_word("--set=growth.bias_input=0.3"), "--set=growth.bias_input=0.3");
}

TEST(ShellWord, QuotesWhatAShellWouldSplitOrExpand) {
  EXPECT_EQ(shell_word(""), "''");
  EXPECT_EQ(shell_word("two words"), "'two words'");
  EXPECT_EQ(shell_word("$HOME"), "'$HOME'");
  EXPECT_EQ(shell_word("it's"), "'it'\\''s'");
}

TEST(ShellWord, AShellReadsTheWordBackAsItWas) {
  for (const std::string w : {"it's \"quoted\" $x `y` \\z", "a\nb", "*"}) {
    FILE* p = popen(("printf %s " + shell_word(w)).c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string back;
    char buf[256];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) back.append(buf, n);
    EXPECT_EQ(pclose(p), 0);
    EXPECT_EQ(back, w);
  }
}

}  // namespace
