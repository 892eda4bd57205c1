#include "study/analysis/figures/csv_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace robozoo {
namespace {

TEST(CsvWriter, HeaderRowsAndQuoting) {
  CsvWriter t({"name", "value"});
  t.add_row({"plain", "1"});
  t.add_row({"with, comma", "say \"hi\""});
  EXPECT_EQ(t.str(), "name,value\nplain,1\n\"with, comma\",\"say \"\"hi\"\"\"\n");
  EXPECT_EQ(t.rows(), 2u);
  EXPECT_THROW(t.add_row({"too", "many", "fields"}), std::invalid_argument);
}

TEST(CsvWriter, Numbers) {
  EXPECT_EQ(csv_number(0.5), "0.5");
  EXPECT_EQ(csv_number(1.0 / 3.0), "0.3333333333");
  EXPECT_EQ(csv_number(std::nan("")), "nan");
  EXPECT_EQ(csv_number(-std::numeric_limits<double>::infinity()), "-inf");
}

}  // namespace
}  // namespace robozoo
