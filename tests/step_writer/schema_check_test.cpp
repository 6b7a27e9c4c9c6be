// The schema check on the negative corpus, the NIST files, and hand-made instances.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/schema_check.hpp"

namespace fs = std::filesystem;
using namespace ncbridge::step_writer;
using namespace ncbridge::step_writer::part21;

namespace {

const express::Schema& iso14649() {
  static const express::Schema schema = express::Schema::parse_file(
      fs::path(NCBRIDGE_SHARED_DIR) / "reference/iso14649/combined_schema_iso14649_only.exp");
  return schema;
}

std::vector<Diagnostic> check_file(const std::string& relative) {
  fs::path path = fs::path(NCBRIDGE_SHARED_DIR) / "corpus" / relative;
  ReadResult read = read_part21_file(path);
  return check_instances(read.graph, iso14649(), {path.string()});
}

std::size_t warnings(const std::vector<Diagnostic>& d) { return d.size() - count_errors(d); }

std::vector<Diagnostic> check_data(const std::string& data) {
  std::string text = "ISO-10303-21;HEADER;FILE_SCHEMA(('MACHINING_SCHEMA'));ENDSEC;DATA;\n" + data +
                     "ENDSEC;END-ISO-10303-21;";
  return check_instances(read_part21(text, "hand.stp").graph, iso14649(), {"hand.stp"});
}

std::string all(const std::vector<Diagnostic>& diagnostics) {
  std::string s;
  for (const auto& d : diagnostics) s += d.to_string() + "\n";
  return s;
}

}  // namespace

TEST(SchemaCheck, BaselineIsClean) {
  auto d = check_file("part21-negative/ex1_fixed_baseline.stp");
  EXPECT_TRUE(d.empty()) << all(d);
}

TEST(SchemaCheck, WrongAttributeCountIsRejectedOnItsLine) {
  auto d = check_file("part21-negative/wrong_attr_count.stp");
  ASSERT_GE(count_errors(d), 1u);
  EXPECT_EQ(d[0].instance, 10u);
  EXPECT_EQ(d[0].entity, "MACHINING_WORKINGSTEP");
  EXPECT_EQ(d[0].where.line, 65u);
  EXPECT_NE(d[0].message.find("has 4 attributes"), std::string::npos) << d[0].message;
  for (const auto& x : d) EXPECT_EQ(x.where.line, 65u) << x.to_string();
}

TEST(SchemaCheck, SwappedReferencesAreRejectedWithTheAttributeNames) {
  auto d = check_file("part21-negative/swapped_refs.stp");
  ASSERT_EQ(count_errors(d), 2u) << all(d);
  EXPECT_EQ(d[0].attribute, "its_feature");
  EXPECT_EQ(d[0].where.line, 65u);
  EXPECT_NE(d[0].message.find("#19 is a PLANE_FINISH_MILLING, not MANUFACTURING_FEATURE"), std::string::npos);
  EXPECT_EQ(d[1].attribute, "its_operation");
  EXPECT_EQ(d[1].to_string().substr(d[1].to_string().size() - 60),
            "#16 is a PLANAR_FACE, not MACHINING_OPERATION (or a subtype)");
}

TEST(SchemaCheck, EveryNegativeFileIsRejectedByReaderOrCheck) {
  int rejected = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(NCBRIDGE_SHARED_DIR) / "corpus/part21-negative")) {
    if (entry.path().filename() == "ex1_fixed_baseline.stp") continue;
    SCOPED_TRACE(entry.path().string());
    try {
      ReadResult read = read_part21_file(entry.path());
      EXPECT_GT(count_errors(check_instances(read.graph, iso14649(), {entry.path().string()})), 0u);
    } catch (const ncbridge::InputError&) {
    }
    ++rejected;
  }
  EXPECT_EQ(rejected, 5);
}

TEST(SchemaCheck, NistFilesGiveWarningsForKnownVariantsOnly) {
  // Same findings as the STEPcode validator (corpus/STEP-PROVENANCE.md): one BIDIRECTIONAL_MILLING,
  // twenty HELIX, nothing else.
  auto ex1 = check_file("stepnc/nist_ex1.stp");
  EXPECT_EQ(count_errors(ex1), 0u) << all(ex1);
  ASSERT_EQ(warnings(ex1), 1u);
  EXPECT_EQ(ex1[0].entity, "BIDIRECTIONAL_MILLING");
  EXPECT_EQ(ex1[0].instance, 42u);
  auto ex1e = check_file("stepnc/nist_ex1E.stp");
  EXPECT_EQ(count_errors(ex1e), 0u) << all(ex1e);
  EXPECT_EQ(warnings(ex1e), 20u);
  for (const auto& w : ex1e) EXPECT_EQ(w.entity, "HELIX");
}

TEST(SchemaCheck, VariantsAreErrorsWhenNotAccepted) {
  fs::path path = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc/nist_ex1.stp";
  CheckOptions strict{path.string(), false};
  auto d = check_instances(read_part21_file(path).graph, iso14649(), strict);
  EXPECT_EQ(count_errors(d), 1u);
}

TEST(SchemaCheck, UnsetRequiredAbstractUnknownEnumAndBounds) {
  auto d = check_data("#1=CARTESIAN_POINT('p',(1.,2.,3.,4.));\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].attribute, "coordinates");
  EXPECT_NE(d[0].message.find("has 4 elements"), std::string::npos) << d[0].message;

  d = check_data("#1=CARTESIAN_POINT($,(1.,2.));\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].attribute, "name");
  EXPECT_NE(d[0].message.find("is not OPTIONAL but is $"), std::string::npos);

  d = check_data("#1=CARTESIAN_POINT('p',(1.,'x'));\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NE(d[0].message.find("element 2: expected a real"), std::string::npos) << d[0].message;

  d = check_data("#1=WORKINGSTEP('w',$);\n");  // abstract, and $ for its_secplane
  EXPECT_EQ(count_errors(d), 2u) << all(d);

  d = check_data("#1=NO_SUCH_THING(1);\n");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].severity, Severity::Error);
  EXPECT_EQ(d[0].where.line, 2u);

  d = check_data("#1=DIRECTION('d',(0.,0.,1));\n#2=CARTESIAN_POINT('p',(0.,0.,0.));\n"
                 "#3=AXIS2_PLACEMENT_3D('a',#2,#1,#1);\n#4=AXIS2_PLACEMENT_3D('b',#1,$,$);\n");
  ASSERT_EQ(d.size(), 1u) << all(d);  // an integer is accepted for a real; #4's location is not a point
  EXPECT_EQ(d[0].instance, 4u);
  EXPECT_EQ(d[0].attribute, "location");
}

TEST(SchemaCheck, EnumerationsBooleansAndSelects) {
  // MILLING_TECHNOLOGY(feedrate, feedrate_reference, cutspeed, spindle, feed_per_tooth, synchronize_spindle_with_feed, inhibit_feedrate_override, inhibit_spindle_override, its_adaptive_control)
  auto good = check_data("#1=MILLING_TECHNOLOGY(0.03,.TCP.,$,-16.,$,.F.,.F.,.F.,$);\n");
  EXPECT_TRUE(good.empty()) << all(good);
  auto bad = check_data("#1=MILLING_TECHNOLOGY(0.03,.TOOLTIP.,$,-16.,$,.X.,.F.,'no',$);\n");
  ASSERT_EQ(bad.size(), 3u) << all(bad);
  EXPECT_EQ(bad[0].attribute, "feedrate_reference");
  EXPECT_NE(bad[0].message.find(".TOOLTIP. is not one of .TCP., .CCP."), std::string::npos) << bad[0].message;
  EXPECT_EQ(bad[1].attribute, "synchronize_spindle_with_feed");
  EXPECT_EQ(bad[2].attribute, "inhibit_spindle_override");
}

TEST(SchemaCheck, DiagnosticsPrintAsFileLineSeverity) {
  auto d = check_file("part21-negative/wrong_attr_count.stp");
  ASSERT_FALSE(d.empty());
  std::string line = d[0].to_string();
  EXPECT_NE(line.find("wrong_attr_count.stp:65: error: #10 MACHINING_WORKINGSTEP: has 4 attributes"), std::string::npos)
      << line;
}

TEST(SchemaCheck, Ap203PartAgainstAp203SchemaOnlyMissesTheSecondSchemasEntities) {
  // Like STEPcode (corpus/STEP-PROVENANCE.md): a one-schema check of a two-schema AP203 file
  // reports the presentation entities of SHAPE_APPEARANCE_LAYER_MIM as unknown, and nothing else.
  // Also exercises complex instances (SI_UNIT redeclares NAMED_UNIT.dimensions as DERIVE: `*`).
  auto schema = express::Schema::parse_file(fs::path(NCBRIDGE_SHARED_DIR) /
                                            "reference/iso14649/ap203_config_control_design.exp");
  fs::path path = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/brep/occt_trj2_io1-ug-203.stp";
  auto d = check_instances(read_part21_file(path).graph, schema, {path.string()});
  ASSERT_FALSE(d.empty());
  std::set<std::string> unknown;
  for (const auto& x : d) {
    EXPECT_NE(x.message.find("is not in schema CONFIG_CONTROL_DESIGN"), std::string::npos) << x.to_string();
    unknown.insert(x.entity);
  }
  EXPECT_TRUE(unknown.count("DRAUGHTING_PRE_DEFINED_COLOUR"));
  EXPECT_TRUE(unknown.count("CURVE_STYLE"));
}
