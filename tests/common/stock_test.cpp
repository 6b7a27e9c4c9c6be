#include "ncbridge/setup/stock.hpp"

#include <gtest/gtest.h>

#include "ncbridge/common/error.hpp"

using namespace ncbridge;
using namespace ncbridge::setup;

TEST(Stock, ReadsCorpusStock) {
  const Stock s = read_stock(NCBRIDGE_SHARED_DIR "/corpus/cam/p01_block_reference/stock.json");
  EXPECT_DOUBLE_EQ(s.min[0], -3);
  EXPECT_DOUBLE_EQ(s.max[1], 83);
  EXPECT_DOUBLE_EQ(s.max[2], 32);
  EXPECT_DOUBLE_EQ(s.size(0), 106);
}

TEST(Stock, InchesAreConverted) {
  const Stock s = parse_stock("units: inch\nmin: [0, 0, -1]\nmax: [4, 2, 0]\n", "s.yaml");
  EXPECT_DOUBLE_EQ(s.max[0], 101.6);
  EXPECT_DOUBLE_EQ(s.min[2], -25.4);
}

TEST(Stock, BadStockIsLocated) {
  try {
    parse_stock("{\"units\": \"mm\",\n \"min\": [0, 0],\n \"max\": [1, 1, 1]}", "s.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2u);
  }
  EXPECT_THROW(parse_stock("{\"min\": [0,0,0], \"max\": [1,1,-1]}", "s.json"), InputError);
  EXPECT_THROW(parse_stock("{\"min\": [0,0,0], \"max\": [1,1,1], \"shape\": \"cylinder\"}", "s.json"), InputError);
  EXPECT_THROW(parse_stock("{\"units\": \"furlong\", \"min\": [0,0,0], \"max\": [1,1,1]}", "s.json"), InputError);
}
