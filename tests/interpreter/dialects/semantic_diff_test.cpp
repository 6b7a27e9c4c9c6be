// ncbridge::step_writer::semantic_diff on small hand-made graphs: matching by content whatever
// the #ids, tolerance, ignored attributes, and the report's rows.
#include <gtest/gtest.h>

#include "ncbridge/step_writer/semantic_diff.hpp"

namespace {

using namespace ncbridge::step_writer;
using namespace ncbridge::step_writer::part21;

// A tool and a workingstep using it, in the given instance order.
Graph make(double x, const std::string& tool_name, bool reversed) {
  Graph g;
  if (reversed) {
    auto p = g.add("CARTESIAN_POINT", {string(""), list_of_reals({x, 2.0, 3.0})});
    auto t = g.add("CUTTING_TOOL", {string(tool_name), integer(1)});
    g.add("WORKINGSTEP", {string("WS1"), ref(t), ref(p)});
  } else {
    auto t = g.add("CUTTING_TOOL", {string(tool_name), integer(1)});
    g.add("COMMENT_ONLY", {string("unrelated")});
    auto p = g.add("CARTESIAN_POINT", {string(""), list_of_reals({x, 2.0, 3.0})});
    g.add("WORKINGSTEP", {string("WS1"), ref(t), ref(p)});
  }
  return g;
}

TEST(SemanticDiff, MatchesByContentNotById) {
  Graph a = make(1.0, "T1", false);
  Graph b = make(1.0, "T1", true);
  b.add("COMMENT_ONLY", {string("unrelated")});
  auto r = semantic_diff(a, b, {});
  EXPECT_TRUE(r.identical()) << format_diff(r, "a", "b");
  EXPECT_EQ(r.matched, 4u);
}

TEST(SemanticDiff, ReportsTheLeafAttributeOnlyAndHonoursTolerance) {
  Graph a = make(1.0, "T1", false);
  Graph b = make(1.5, "T1", true);
  b.add("COMMENT_ONLY", {string("unrelated")});
  auto r = semantic_diff(a, b, {});
  ASSERT_FALSE(r.identical());
  ASSERT_EQ(r.differences.size(), 1u) << format_diff(r, "a", "b");
  EXPECT_EQ(r.differences[0].entity, "CARTESIAN_POINT");
  EXPECT_EQ(r.differences[0].attribute, "#2");
  EXPECT_EQ(r.changed_through_parts, 1u);  // the workingstep, through its point
  std::string report = format_diff(r, "a.stp", "b.stp");
  EXPECT_NE(report.find("CARTESIAN_POINT"), std::string::npos);
  EXPECT_NE(report.find("(1, 2, 3)"), std::string::npos);
  EXPECT_NE(report.find("(1.5, 2, 3)"), std::string::npos);
  DiffOptions loose;
  loose.tolerance = 0.6;
  EXPECT_TRUE(semantic_diff(a, b, loose).identical());
}

TEST(SemanticDiff, IgnoredAttributesDoNotCount) {
  Graph a = make(1.0, "T1", false);
  Graph b = make(1.0, "FACEMILL", false);
  EXPECT_FALSE(semantic_diff(a, b, {}).identical());
  DiffOptions options;
  options.ignore = {"CUTTING_TOOL.1"};
  EXPECT_TRUE(semantic_diff(a, b, options).identical());
  options.ignore = {"*.1"};
  EXPECT_TRUE(semantic_diff(a, b, options).identical());
}

TEST(SemanticDiff, InstancesOnlyOneSideHas) {
  Graph a = make(1.0, "T1", false);
  Graph b = make(1.0, "T1", false);
  b.add("CUTTING_TOOL", {string("T2"), integer(2)});
  auto r = semantic_diff(a, b, {});
  EXPECT_TRUE(r.only_a.empty());
  ASSERT_EQ(r.only_b.size(), 1u);
  EXPECT_EQ(r.only_b[0].entity, "CUTTING_TOOL");
  EXPECT_NE(format_diff(r, "a", "b").find("only in B"), std::string::npos);
}

}  // namespace

TEST(SemanticDiff, LeftOutEntitiesTakeWhatOnlyTheyUse) {
  auto make_plan = [](double y, bool extra_point) {
    Graph g;
    auto feature = g.add("CARTESIAN_POINT", {string("hole"), list_of_reals({5.0, 5.0, 0.0})});
    std::vector<InstanceId> points;
    points.push_back(g.add("CARTESIAN_POINT", {string(""), list_of_reals({0.0, y, 0.0})}));
    if (extra_point) points.push_back(g.add("CARTESIAN_POINT", {string(""), list_of_reals({1.0, y, 0.0})}));
    auto path = g.add("POLYLINE", {string(""), list_of_refs(points)});
    auto toolpaths = g.add("TOOLPATH_LIST", {list_of_refs({path})});
    g.add("WORKINGSTEP", {string("WS"), ref(feature), ref(toolpaths)});
    return g;
  };
  Graph a = make_plan(0.0, false);
  Graph b = make_plan(3.0, true);
  EXPECT_FALSE(semantic_diff(a, b, {}).identical());
  DiffOptions options;
  options.ignore_entities = {"TOOLPATH_LIST"};
  auto r = semantic_diff(a, b, options);
  EXPECT_TRUE(r.identical()) << format_diff(r, "a", "b");
  EXPECT_EQ(r.instances_a, 2u);  // the workingstep and the feature's point
  Graph c = make_plan(0.0, false);
  c.add("CARTESIAN_POINT", {string("another"), list_of_reals({9.0, 9.0, 0.0})});
  EXPECT_FALSE(semantic_diff(a, c, options).identical());
}
