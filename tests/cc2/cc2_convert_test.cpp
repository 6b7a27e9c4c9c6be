// `ncbridge convert --level cc2` end to end, through our interpreter, on the corpus programs
// with every comment stripped (recognition must never read them), scored against truth.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "ncbridge/feature_recognizer/scoring.hpp"
#include "ncbridge/step_writer/express_schema.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/schema_check.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace fr = ncbridge::feature_recognizer;
namespace sw = ncbridge::step_writer;
namespace fs = std::filesystem;

namespace {

const fs::path kShared = NCBRIDGE_SHARED_DIR;
const fs::path kNcbridge = fs::path(NCBRIDGE_BINARY_DIR) / "bin" / "ncbridge";

struct Case {
  std::string name;
  fs::path program, dir;
  std::string truth_program;  // key in the paper's truth.json
};

Case part(const std::string& name) {
  const fs::path dir = fs::path(NCBRIDGE_SOURCE_DIR) / "tests" / "cc2" / "parts" / name;
  return {name, dir / "part.ngc", dir, ""};
}

std::vector<Case> corpus() {
  const fs::path cam = kShared / "corpus" / "cam", paper = kShared / "corpus" / "paper";
  return {{"p01_block_reference", cam / "p01_block_reference" / "part.nc", cam / "p01_block_reference", ""},
          {"p02_plate_center_zero", cam / "p02_plate_center_zero" / "part.linuxcnc.ngc", cam / "p02_plate_center_zero", ""},
          {"p03_bracket_steps", cam / "p03_bracket_steps" / "part.nc", cam / "p03_bracket_steps", ""},
          {"p04_open_pockets", cam / "p04_open_pockets" / "part.linuxcnc.ngc", cam / "p04_open_pockets", ""},
          {"p05_slots", cam / "p05_slots" / "part.nc", cam / "p05_slots", ""},
          {"paper_face_mill", paper / "face_mill.ngc", paper, "face_mill.ngc"},
          {"paper_test_part", paper / "test_part.ngc", paper, "test_part.ngc"},
          // Hand-designed parts of other shapes and strategies (parts/make_parts.py).
          part("p06_nested_pockets"), part("p07_helix_holes"), part("p08_multi_level"), part("p09_small_part"),
          part("p10_plate"), part("p11_slots_rotated_pocket"), part("p12_freecad_style"), part("p13_hsm_style"),
          part("p14_shop_program"), part("p15_hobby_style")};
}

Case named(const std::string& name) {
  for (auto& c : corpus()) {
    if (c.name == name) return c;
  }
  throw std::runtime_error("no case " + name);
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path work_dir() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "_" + info->name();
  for (char& ch : name) {
    if (ch == '/') ch = '_';
  }
  const fs::path d = fs::temp_directory_path() / ("ncbridge_cc2_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The program with every comment removed: `(...)` and `;...` (as the recogniser's corpus data).
fs::path stripped_copy(const Case& c, const fs::path& dir) {
  std::string text = read_file(c.program);
  text = std::regex_replace(text, std::regex(R"(\([^)\n]*\))"), "");
  text = std::regex_replace(text, std::regex(";[^\n]*"), "");
  const fs::path out = dir / (c.name + ".ngc");
  std::ofstream(out, std::ios::binary) << text;
  return out;
}

struct CommandResult {
  int exit_code = -1;
  std::string err;
};

CommandResult run_ncbridge(const std::string& arguments, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt";
  const std::string command = "SOURCE_DATE_EPOCH=1700000000 '" + kNcbridge.string() + "' " + arguments + " 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(err)};
}

std::string convert_args(const Case& c, const fs::path& program, const fs::path& out) {
  return "convert '" + program.string() + "' --tools '" + (c.dir / "tools.json").string() + "' --stock '" +
         (c.dir / "stock.json").string() + "' --level cc2 -o '" + out.string() + "'";
}

// The report's features as recogniser features (what the scorer compares).
std::vector<fr::RecognizedFeature> report_features(const fs::path& report) {
  std::vector<fr::RecognizedFeature> out;
  for (const auto& t : fr::read_truth(report)) {
    fr::RecognizedFeature f;
    f.type = t.type;
    f.x = t.x, f.y = t.y, f.top_z = t.top_z, f.bottom_z = t.bottom_z;
    f.diameter = t.diameter.value_or(0);
    for (const auto& o : t.operations) {
      fr::RecognizedOperation op;
      op.type = o.type, op.tool_number = o.tool_number, op.strategy = o.strategies.empty() ? fr::Strategy::None : o.strategies.front();
      f.operations.push_back(op);
    }
    if (t.type == fr::FeatureType::Slot && !t.closed) f.slot_ends = {fr::SlotEnd::Open, fr::SlotEnd::Open};
    if (t.type == fr::FeatureType::Slot && t.closed) f.slot_ends = {fr::SlotEnd::Radiused, fr::SlotEnd::Radiused};
    out.push_back(f);
  }
  return out;
}

const sw::express::Schema& schema() {
  static const auto s =
      sw::express::Schema::parse_file(kShared / "reference" / "iso14649" / "combined_schema_iso14649_only.exp");
  return s;
}

}  // namespace

class CommentFreeCorpus : public testing::TestWithParam<std::string> {};

TEST_P(CommentFreeCorpus, Cc2ReportScoresF1AtLeast95AndTheFileIsSchemaValid) {
  const Case c = named(GetParam());
  const fs::path dir = work_dir();
  const fs::path program = stripped_copy(c, dir);
  ASSERT_EQ(read_file(program).find('('), std::string::npos);
  const CommandResult run = run_ncbridge(convert_args(c, program, dir / "part.stp") + " --report '" + (dir / "report.json").string() + "'", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;

  const auto found = report_features(dir / "report.json");
  const auto truth = fr::read_truth(c.dir / "truth.json", c.truth_program);
  const auto s = fr::score(found, truth);
  for (const auto& [type, t] : s.per_type) {
    EXPECT_GE(t.f1(), 0.95) << fr::to_string(type) << ": truth " << t.truth << ", found " << t.recognized << ", matched " << t.matched;
  }
  EXPECT_GE(s.overall.f1(), 0.95);
  RecordProperty("f1", std::to_string(s.overall.f1()));
  // Where the truth lists the operations, the report's operations of each matched feature agree.
  const auto ops = fr::score_operations(found, truth, s);
  EXPECT_EQ(ops.matched, ops.truth);
  EXPECT_EQ(ops.recognized, ops.truth);

  const auto read = sw::part21::read_part21_file(dir / "part.stp");
  const auto diagnostics = sw::check_instances(read.graph, schema());
  EXPECT_EQ(sw::count_errors(diagnostics), 0u);
  for (const auto& d : diagnostics) ADD_FAILURE() << d.to_string();
}

TEST_P(CommentFreeCorpus, WriteReadWriteIsByteIdentical) {
  const Case c = named(GetParam());
  const fs::path dir = work_dir();
  const CommandResult run = run_ncbridge(convert_args(c, stripped_copy(c, dir), dir / "part.stp"), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string text = read_file(dir / "part.stp");
  const auto read = sw::read_stepnc(text, "part.stp");
  EXPECT_TRUE(read.warnings.empty()) << read.warnings.front().to_string();
  sw::StepncWriteOptions options;
  options.file_name = "part.stp";
  options.description = {"ISO 14649 CC2 program written by ncbridge"};
  options.unix_time = 1700000000;
  EXPECT_EQ(sw::write_stepnc(read.project, options), text);
}

TEST_P(CommentFreeCorpus, ACc1FileGivesTheSameCc2AsItsProgram) {
  const Case c = named(GetParam());
  const fs::path dir = work_dir();
  const fs::path program = stripped_copy(c, dir);
  fs::create_directories(dir / "direct");
  fs::create_directories(dir / "via_cc1");
  ASSERT_EQ(run_ncbridge(convert_args(c, program, dir / "direct" / "part.stp"), dir).exit_code, 0);
  const CommandResult cc1 = run_ncbridge("convert '" + program.string() + "' --tools '" + (c.dir / "tools.json").string() + "' --stock '" +
                               (c.dir / "stock.json").string() + "' -o '" + (dir / "part_cc1.stp").string() + "'",
                           dir);
  ASSERT_EQ(cc1.exit_code, 0) << cc1.err;
  const CommandResult cc2 = run_ncbridge("convert '" + (dir / "part_cc1.stp").string() + "' --level cc2 -o '" + (dir / "via_cc1" / "part.stp").string() + "'", dir);
  ASSERT_EQ(cc2.exit_code, 0) << cc2.err;
  const std::string direct = read_file(dir / "direct" / "part.stp");
  EXPECT_FALSE(direct.empty());
  EXPECT_EQ(read_file(dir / "via_cc1" / "part.stp"), direct);
}

INSTANTIATE_TEST_SUITE_P(Parts, CommentFreeCorpus,
                         testing::Values("p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps",
                                         "p04_open_pockets", "p05_slots", "paper_face_mill", "paper_test_part",
                                         "p06_nested_pockets", "p07_helix_holes", "p08_multi_level", "p09_small_part",
                                         "p10_plate", "p11_slots_rotated_pocket", "p12_freecad_style",
                                         "p13_hsm_style", "p14_shop_program", "p15_hobby_style"));

TEST(Cc2Convert, SameInputSameBytes) {
  const Case c = named("paper_test_part");
  const fs::path dir = work_dir();
  const fs::path program = stripped_copy(c, dir);
  const fs::path a = dir / "a.stp";
  ASSERT_EQ(run_ncbridge(convert_args(c, program, a) + " --report '" + (dir / "a.json").string() + "'", dir).exit_code, 0);
  fs::rename(a, dir / "keep.stp");
  ASSERT_EQ(run_ncbridge(convert_args(c, program, a), dir).exit_code, 0);
  EXPECT_EQ(read_file(dir / "keep.stp"), read_file(a));
  EXPECT_NE(read_file(a).find("FILE_NAME('a.stp','2023-11-14T22:13:20'"), std::string::npos);
}

TEST(Cc2Convert, HtmlPageIsSelfContainedAndShowsEveryFeature) {
  const Case c = named("p01_block_reference");
  const fs::path dir = work_dir();
  const fs::path html = dir / "part.html", report = dir / "part.json";
  const CommandResult run = run_ncbridge(convert_args(c, stripped_copy(c, dir), dir / "part.stp") + " --report '" + report.string() +
                               "' --html '" + html.string() + "'",
                           dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string page = read_file(html);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("<svg"), std::string::npos);
  // No external resources. The scripts are inline (three.js, inlined, mentions URLs in its code
  // and comments): each script tag has no src, and outside the scripts the SVG namespace is the
  // only URL.
  std::string markup;
  for (std::size_t at = 0;;) {
    const std::size_t open = page.find("<script", at);
    markup += page.substr(at, open == std::string::npos ? std::string::npos : open - at);
    if (open == std::string::npos) break;
    const std::size_t tag_end = page.find('>', open);
    ASSERT_NE(tag_end, std::string::npos);
    const std::string tag = page.substr(open, tag_end + 1 - open);
    EXPECT_TRUE(tag == "<script>" || tag == "<script type=\"application/json\" id=\"ncb-data\">") << tag;
    const std::size_t close = page.find("</script>", tag_end);
    ASSERT_NE(close, std::string::npos);
    at = close + 9;
  }
  EXPECT_EQ(markup.find("src="), std::string::npos);
  EXPECT_EQ(markup.find("href="), std::string::npos);
  EXPECT_EQ(markup.find("https://"), std::string::npos);
  EXPECT_NE(page.find("THREE"), std::string::npos);  // the 3D view's library, inlined
  const auto features = nlohmann::json::parse(read_file(report))["features"];
  ASSERT_EQ(features.size(), 7u);
  for (const auto& f : features) EXPECT_NE(page.find(f["id"].get<std::string>()), std::string::npos) << f["id"];
  EXPECT_NE(page.find("T4 Drill_D10"), std::string::npos);  // the tools table
}

TEST(Cc2Convert, ReportFeaturesFollowTheDocumentedShape) {
  const Case c = named("paper_test_part");
  const fs::path dir = work_dir();
  ASSERT_EQ(run_ncbridge(convert_args(c, stripped_copy(c, dir), dir / "part.stp") + " --report '" + (dir / "r.json").string() + "'", dir)
                .exit_code,
            0);
  const auto report = nlohmann::json::parse(read_file(dir / "r.json"));
  EXPECT_EQ(report["level"], "cc2");
  EXPECT_TRUE(report["timings_ms"].contains("feature_recognizer"));
  const auto& features = report["features"];
  ASSERT_EQ(features.size(), 3u);
  const auto& pocket = features[1];
  EXPECT_EQ(pocket["type"], "closed_pocket");
  EXPECT_NEAR(pocket["center_xy"][0].get<double>(), 70, 0.01);
  EXPECT_NEAR(pocket["center_xy"][1].get<double>(), 70, 0.01);
  EXPECT_NEAR(pocket["depth"].get<double>(), 30, 1e-6);
  EXPECT_NEAR(pocket["dimensions"]["length"].get<double>(), 80, 0.05);
  EXPECT_NEAR(pocket["dimensions"]["width"].get<double>(), 50, 0.05);
  EXPECT_NEAR(pocket["dimensions"]["corner_radius"].get<double>(), 10, 0.2);
  EXPECT_NEAR(pocket["dimensions"]["angle_deg"].get<double>(), 90, 1e-6);
  EXPECT_EQ(pocket["bottom_condition"], "planar");
  ASSERT_EQ(pocket["operations"].size(), 2u);
  EXPECT_EQ(pocket["operations"][0]["type"], "bottom_and_side_rough_milling");
  EXPECT_EQ(pocket["operations"][0]["tool_number"], 1);
  EXPECT_EQ(pocket["operations"][0]["strategy"], "contour_parallel");
  EXPECT_EQ(pocket["operations"][1]["type"], "bottom_and_side_finish_milling");
  const auto& hole = features[2];
  EXPECT_EQ(hole["type"], "round_hole");
  EXPECT_EQ(hole["bottom_condition"], "through");
  EXPECT_NEAR(hole["dimensions"]["diameter"].get<double>(), 22, 1e-9);
  EXPECT_EQ(hole["operations"][1]["type"], "reaming");
  EXPECT_EQ(hole["operations"][1]["tool_number"], 3);
  // The workplan lists the CC2 workingsteps, each naming its feature.
  int machining = 0;
  for (const auto& w : report["workingsteps"]) {
    if (w["kind"] != "MACHINING_WORKINGSTEP") continue;
    ++machining;
    EXPECT_TRUE(w.contains("feature"));
  }
  EXPECT_EQ(machining, 5);
}

TEST(Cc2Convert, Cc1FileWithoutRawpieceNeedsStockAndNonsenseInputIsAnErrorWithItsFile) {
  const fs::path dir = work_dir();
  const fs::path bad = dir / "bad.stp";
  std::ofstream(bad) << "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=FOO(1.);\nENDSEC;\nEND-ISO-10303-21;\n";
  const CommandResult run = run_ncbridge("convert '" + bad.string() + "' --level cc2 -o '" + (dir / "out.stp").string() + "'", dir);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("bad.stp"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("no PROJECT"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out.stp"));

  const CommandResult no_tools = run_ncbridge("convert '" + (kShared / "corpus" / "paper" / "face_mill.ngc").string() + "' --level cc2 -o '" +
                                    (dir / "out.stp").string() + "'",
                                dir);
  EXPECT_EQ(no_tools.exit_code, 2);  // a usage error (docs/cli.md)
  EXPECT_NE(no_tools.err.find("needs --tools (or --tool-table) and --stock"), std::string::npos) << no_tools.err;
}

TEST(Cc2Convert, NistExample1IsReadAsInputAndKeepsEveryWorkingstep) {
  // ISO 14649-11 example 1 (comments before the header, no milling toolpaths, no rawpiece): the
  // hole is recognised from its drilling cycles, the face and pocket stay as the file gave them.
  const fs::path dir = work_dir();
  const fs::path out = dir / "nist.stp", report = dir / "nist.json";
  const CommandResult run = run_ncbridge("convert '" + (kShared / "corpus" / "stepnc" / "nist_ex1.stp").string() +
                                             "' --level cc2 --stock '" + (kShared / "corpus" / "paper" / "stock.json").string() +
                                             "' -o '" + out.string() + "' --report '" + report.string() + "'",
                                         dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto r = nlohmann::json::parse(read_file(report));
  int machining = 0;
  for (const auto& w : r["workingsteps"]) machining += w["kind"] == "MACHINING_WORKINGSTEP";
  EXPECT_EQ(machining, 5);
  ASSERT_EQ(r["features"].size(), 1u);
  EXPECT_EQ(r["features"][0]["type"], "round_hole");
  const auto text = read_file(out);
  EXPECT_NE(text.find("PLANAR_FACE('PLANAR FACE1'"), std::string::npos);
  EXPECT_NE(text.find("CLOSED_POCKET('POCKET1'"), std::string::npos);
  const auto diagnostics = sw::check_instances(sw::part21::read_part21_file(out).graph, schema());
  EXPECT_EQ(sw::count_errors(diagnostics), 0u);
}
