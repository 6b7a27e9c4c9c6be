// Tool data shops have: FreeCAD tool bits and libraries, Fusion 360 tool library exports, and a
// tool list in inches. The examples beside the plate (examples/plate/) hold the plate's three
// tools in each format; each must read as the same tools as examples/plate/tools.json.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <unistd.h>
#include <string>

#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/freecad_tools.hpp"
#include "ncbridge/setup/fusion_tools.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace {

using namespace ncbridge;
using namespace ncbridge::setup;
namespace fs = std::filesystem;

const fs::path kPlate = fs::path(NCBRIDGE_SOURCE_DIR) / "examples" / "plate";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ncbridge_tool_data_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void put(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// The dimensions the conversion uses, as tools.json gives them.
void expect_plate_tools(const ToolList& tools, double tolerance, bool face_mill_typed = true) {
  ASSERT_EQ(tools.tools().size(), 3u);
  const ToolList reference = read_tool_list(kPlate / "tools.json");
  for (const Tool& want : reference.tools()) {
    const Tool* got = tools.find(want.number);
    ASSERT_NE(got, nullptr) << "T" << want.number;
    EXPECT_EQ(got->name, want.name);
    if (face_mill_typed || want.type != ToolType::FaceMill) {
      EXPECT_EQ(got->type, want.type) << "T" << want.number;
    }
    EXPECT_NEAR(got->diameter, want.diameter, tolerance) << "T" << want.number;
    EXPECT_NEAR(got->length, want.length, tolerance) << "T" << want.number;
    EXPECT_NEAR(got->flute_length, want.flute_length, tolerance) << "T" << want.number;
    EXPECT_EQ(got->flutes, want.flutes) << "T" << want.number;
    EXPECT_DOUBLE_EQ(got->point_angle, want.point_angle) << "T" << want.number;
  }
}

SourceLocation error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.where();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(ToolData, AFusionLibraryExportReadsAsThePlateTools) {
  const ToolList tools = read_tool_list(kPlate / "tools_fusion.json");  // its holder is skipped
  expect_plate_tools(tools, 0);
  EXPECT_DOUBLE_EQ(tools.find(1)->spindle_rpm, 2400);
  EXPECT_DOUBLE_EQ(tools.find(1)->feed, 1200);
  EXPECT_DOUBLE_EQ(tools.find(1)->plunge_feed, 300);
  EXPECT_EQ(tools.find(2)->pocket, 2);
}

TEST(ToolData, AFreeCadLibraryFindsItsBitsInTheBitFolder) {
  // FreeCAD has no face mill shape: the D50 is an end mill there.
  const ToolList tools = read_tool_list(kPlate / "freecad" / "Library" / "plate.fctl");
  expect_plate_tools(tools, 0, false);
  EXPECT_EQ(tools.find(1)->type, ToolType::FlatEndMill);
}

TEST(ToolData, AToolListInInches) {
  expect_plate_tools(read_tool_list(kPlate / "tools_inch.yaml"), 1e-4);
}

TEST(ToolData, FreeCadQuantitiesShapesAndALoneBit) {
  const fs::path dir = scratch("bits");
  put(dir / "bull.fctb", R"({"version": 2, "name": "6 mm bull nose", "shape": "bullnose.fcstd",
    "parameter": {"Diameter": "0.25 in", "FlatRadius": "2 mm", "Length": "5 cm", "CuttingEdgeHeight": "12 mm"}})");
  const ToolList bull = read_tool_list(dir / "bull.fctb");
  ASSERT_EQ(bull.tools().size(), 1u);
  const Tool& t = bull.tools().front();
  EXPECT_EQ(t.number, 1);  // as FreeCAD numbers a bit added without a library
  EXPECT_EQ(t.type, ToolType::BullNoseEndMill);
  EXPECT_DOUBLE_EQ(t.diameter, 6.35);
  EXPECT_DOUBLE_EQ(t.corner_radius, 6.35 / 2 - 2);
  EXPECT_DOUBLE_EQ(t.length, 50);

  const Tool tap = parse_freecad_tool_bit(R"({"name": "3/8-16", "shape": "tap.fcstd",
    "parameter": {"Diameter": "0.375 \"", "Length": "2.5 \"", "Pitch": "0.000 in", "TPI": "16"}})", "tap.fctb", 7);
  EXPECT_EQ(tap.type, ToolType::Tap);
  EXPECT_DOUBLE_EQ(tap.diameter, 9.525);
  EXPECT_DOUBLE_EQ(tap.thread_pitch, 25.4 / 16);

  const Tool probe = parse_freecad_tool_bit(R"({"name": "probe", "shape": "probe.fcstd",
    "parameter": {"Diameter": "2 mm", "Length": "50 mm"}})", "probe.fctb", 9);
  EXPECT_EQ(probe.type, ToolType::Unknown);  // read; the setup checks say a tool has no type
}

TEST(ToolData, ErrorsNameTheFileLineAndColumn) {
  const SourceLocation unit = error_of([] {
    parse_freecad_tool_bit("{\"name\": \"x\", \"shape\": \"endmill.fcstd\",\n \"parameter\": {\"Diameter\": \"6 kg\"}}", "x.fctb", 1);
  });
  EXPECT_EQ(unit.file, "x.fctb");
  EXPECT_EQ(unit.line, 2u);
  EXPECT_GT(unit.column, 1u);

  const fs::path dir = scratch("library");
  put(dir / "Library" / "shop.fctl", "{\"tools\": [\n  {\"nr\": 1, \"path\": \"missing.fctb\"}\n]}");
  const SourceLocation missing = error_of([&] { read_tool_list(dir / "Library" / "shop.fctl"); });
  EXPECT_EQ(missing.file, (dir / "Library" / "shop.fctl").string());
  EXPECT_EQ(missing.line, 2u);

  put(dir / "Library" / "twice.fctl", "{\"tools\": [{\"nr\": 1, \"path\": \"a.fctb\"},\n {\"nr\": 1, \"path\": \"a.fctb\"}]}");
  put(dir / "Bit" / "a.fctb", R"({"name": "a", "shape": "endmill.fcstd", "parameter": {"Diameter": "3 mm"}})");
  EXPECT_EQ(error_of([&] { read_tool_list(dir / "Library" / "twice.fctl"); }).line, 2u);

  const SourceLocation fusion_unit = error_of([] {
    parse_tool_list("{\"data\": [\n {\"type\": \"drill\", \"unit\": \"furlongs\", \"post-process\": {\"number\": 1}}]}", "f.json");
  });
  EXPECT_EQ(fusion_unit.line, 2u);
  const SourceLocation no_number = error_of([] { parse_tool_list("{\"data\": [{\"type\": \"drill\"}]}", "f.json"); });
  EXPECT_EQ(no_number.file, "f.json");

  EXPECT_EQ(error_of([] { parse_tool_list("units: cubits\ntools: []\n", "t.yaml"); }).line, 1u);
  EXPECT_EQ(error_of([] { parse_tool_list("PK\x03\x04zip", "lib.tools"); }).line, 1u);
  EXPECT_EQ(error_of([&] { read_tool_list(kPlate / "tools.tbl"); }).file, (kPlate / "tools.tbl").string());
}

TEST(ToolData, AKeyWithoutAValueIsNotGiven) {  // found by fuzz_tool_list: it threw a yaml-cpp exception
  const ToolList tools = parse_tool_list("- {number: 1, diameter: 6, length: }\n", "t.yaml");
  EXPECT_DOUBLE_EQ(tools.find(1)->length, 0);
  EXPECT_EQ(error_of([] { parse_tool_list("- {number: 1, diameter: -6}\n", "t.yaml"); }).line, 1u);
}

TEST(ToolData, AFusionInchToolAndTypesWithoutACounterpart) {
  const ToolList tools = parse_fusion_tool_library(R"({"data": [
    {"type": "bull nose end mill", "unit": "inches", "description": "1/2 bull",
     "geometry": {"DC": 0.5, "OAL": 3, "RE": 0.03, "NOF": 4},
     "post-process": {"number": 12, "turret": 4},
     "start-values": {"presets": [{"n": 8000, "v_f": 40, "v_f_plunge": 10}]}},
    {"type": "thread mill", "unit": "millimeters", "geometry": {"DC": 10}, "post-process": {"number": 13}}]})",
                                                   "f.json");
  const Tool* bull = tools.find(12);
  ASSERT_NE(bull, nullptr);
  EXPECT_EQ(bull->type, ToolType::BullNoseEndMill);
  EXPECT_DOUBLE_EQ(bull->diameter, 12.7);
  EXPECT_DOUBLE_EQ(bull->corner_radius, 0.03 * 25.4);
  EXPECT_DOUBLE_EQ(bull->feed, 40 * 25.4);
  EXPECT_DOUBLE_EQ(bull->spindle_rpm, 8000);
  EXPECT_EQ(bull->pocket, 4);
  EXPECT_EQ(tools.find(13)->type, ToolType::Unknown);
}

}  // namespace
