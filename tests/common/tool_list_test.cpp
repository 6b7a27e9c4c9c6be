#include "ncbridge/setup/tool_list.hpp"

#include <gtest/gtest.h>

#include "ncbridge/common/error.hpp"

using namespace ncbridge;
using namespace ncbridge::setup;

TEST(ToolList, ReadsThePaperToolList) {
  const ToolList tools = read_tool_list(NCBRIDGE_SHARED_DIR "/corpus/paper/tools.json");
  ASSERT_EQ(tools.tools().size(), 3u);
  const Tool* t1 = tools.find(1);
  ASSERT_NE(t1, nullptr);
  EXPECT_EQ(t1->name, "ENDMILL_18MM");
  EXPECT_EQ(t1->type, ToolType::FlatEndMill);
  EXPECT_DOUBLE_EQ(t1->diameter, 18);
  EXPECT_DOUBLE_EQ(t1->length, 50);
  EXPECT_DOUBLE_EQ(t1->flute_length, 29);
  EXPECT_EQ(t1->flutes, 4);
  EXPECT_DOUBLE_EQ(tools.find(2)->point_angle, 118);
  EXPECT_EQ(tools.find(3)->type, ToolType::Reamer);
  EXPECT_EQ(tools.find(4), nullptr);
}

TEST(ToolList, ReadsEveryCamCorpusToolListWithFreeCadNames) {
  for (const char* part : {"p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps",
                           "p04_open_pockets", "p05_slots"}) {
    const ToolList tools =
        read_tool_list(std::string(NCBRIDGE_SHARED_DIR "/corpus/cam/") + part + "/tools.json");
    EXPECT_FALSE(tools.empty()) << part;
    for (const Tool& t : tools.tools()) {
      EXPECT_NE(t.type, ToolType::Unknown) << part << " T" << t.number;
      EXPECT_GT(t.diameter, 0) << part << " T" << t.number;
    }
  }
}

TEST(ToolList, CuttingDataOfTheShop) {
  const ToolList tools = read_tool_list(NCBRIDGE_SHARED_DIR "/corpus/cam/p01_block_reference/tools.json");
  const Tool* face = tools.find(1);
  ASSERT_NE(face, nullptr);
  EXPECT_DOUBLE_EQ(face->spindle_rpm, 2500);
  EXPECT_DOUBLE_EQ(face->feed, 1200);
  EXPECT_DOUBLE_EQ(face->plunge_feed, 300);
  const ToolList paper = read_tool_list(NCBRIDGE_SHARED_DIR "/corpus/paper/tools.json");
  EXPECT_DOUBLE_EQ(paper.find(1)->feed, 0);  // not given
  EXPECT_THROW(parse_tool_list(R"([{"number": 1, "feed": -5}])", "t.json"), InputError);
}

TEST(ToolList, YamlFormIsAccepted) {
  const ToolList tools = parse_tool_list(
      "tools:\n  - {number: 7, type: ball_end_mill, diameter: 6, corner_radius: 3}\n"
      "  - number: 2\n    type: spot_drill\n    diameter: 10\n    unknown_field: ignored\n",
      "t.yaml");
  ASSERT_EQ(tools.tools().size(), 2u);
  EXPECT_EQ(tools.tools()[0].number, 2);  // sorted
  EXPECT_EQ(tools.find(7)->type, ToolType::BallEndMill);
  EXPECT_DOUBLE_EQ(tools.find(7)->corner_radius, 3);
}

TEST(ToolList, ErrorsNameTheLine) {
  try {
    parse_tool_list("[\n {\"number\": 1, \"type\": \"drill\"},\n {\"number\": 2, \"type\": \"spoon\"}\n]", "bad.json");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "bad.json");
    EXPECT_EQ(e.where().line, 3u);
    EXPECT_NE(e.message().find("spoon"), std::string::npos);
  }
  EXPECT_THROW(parse_tool_list("[{\"name\": \"no number\"}]", "x.json"), InputError);
  EXPECT_THROW(parse_tool_list("[{\"number\": 1}, {\"number\": 1}]", "x.json"), InputError);
  EXPECT_THROW(parse_tool_list("[{\"number\": 1, \"diameter\": \"wide\"}]", "x.json"), InputError);
  EXPECT_THROW(parse_tool_list("{\"number\": 1", "x.json"), InputError);
}

TEST(LinuxCncToolTable, ReadsMetricAndInchTables) {
  const ToolList mm = parse_linuxcnc_tool_table("T1 P1 D18.0 Z+50.0 ;ENDMILL 18\n\n;only a comment\nT2 P5 D20 Z70\n",
                                                LengthUnits::Millimeters, "t.tbl");
  ASSERT_EQ(mm.tools().size(), 2u);
  EXPECT_EQ(mm.find(1)->name, "ENDMILL 18");
  EXPECT_DOUBLE_EQ(mm.find(1)->length, 50);
  EXPECT_EQ(mm.find(2)->pocket, 5);
  const ToolList in = parse_linuxcnc_tool_table("T3 P3 D0.5 Z2.0\n", LengthUnits::Inches, "t.tbl");
  EXPECT_DOUBLE_EQ(in.find(3)->diameter, 12.7);
  EXPECT_DOUBLE_EQ(in.find(3)->length, 50.8);
}

TEST(LinuxCncToolTable, RejectsWhatLinuxCncSilentlyIgnores) {
  try {
    parse_linuxcnc_tool_table("T1 P1 D6\nT2 P2 Dwide\n", LengthUnits::Millimeters, "t.tbl");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2u);
    EXPECT_EQ(e.where().column, 7u);
  }
  EXPECT_THROW(parse_linuxcnc_tool_table("P1 D6\n", LengthUnits::Millimeters, "t.tbl"), InputError);
  EXPECT_THROW(parse_linuxcnc_tool_table("T1 K3\n", LengthUnits::Millimeters, "t.tbl"), InputError);
}
