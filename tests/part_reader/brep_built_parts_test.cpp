// Parts built with Open CASCADE in the test and exported as STEP, then read back: the
// SolidWorks-style circular pocket (its cylinder split in two faces, its circles in halves on the
// top face), a hole in a pocket's floor (two features, not one), drill points and a countersink,
// a rounded rectangular pocket, a part written in metres; and a STEP file without a solid.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <ShapeUpgrade_ShapeDivideClosed.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pln.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "ncbridge/common/error.hpp"
#include "ncbridge/part_reader/brep_reader.hpp"

namespace pr = ncbridge::part_reader;
namespace fs = std::filesystem;

namespace {

fs::path written(const TopoDS_Shape& shape, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "ncbridge_built_parts";
  fs::create_directories(dir);
  const fs::path file = dir / name;
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  STEPControl_Writer writer;
  EXPECT_EQ(writer.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
  EXPECT_EQ(writer.Write(file.string().c_str()), IFSelect_RetDone);
  return file;
}

TopoDS_Shape block() { return BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 100, 80, 20).Shape(); }

// A cylinder standing on z = bottom up past the top, at (x, y).
TopoDS_Shape tool(double x, double y, double r, double bottom) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, bottom), gp_Dir(0, 0, 1)), r, 30).Shape();
}

int cylinder_faces(const TopoDS_Shape& shape) {
  int n = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    if (BRepAdaptor_Surface(TopoDS::Face(e.Current())).GetType() == GeomAbs_Cylinder) ++n;
  }
  return n;
}

std::vector<const pr::Feature*> of_kind(const pr::Part& part, pr::FeatureKind kind) {
  std::vector<const pr::Feature*> out;
  for (const auto& f : part.features) {
    if (f.kind == kind) out.push_back(&f);
  }
  return out;
}

}  // namespace

TEST(BuiltParts, SolidWorksStyleCircularPocketSplitInTwoFaces) {
  TopoDS_Shape part = BRepAlgoAPI_Cut(block(), tool(50, 40, 20, 12)).Shape();
  ShapeUpgrade_ShapeDivideClosed divide(part);
  divide.SetNbSplitPoints(1);  // every closed face in two halves, as SolidWorks exports them
  ASSERT_TRUE(divide.Perform());
  part = divide.Result();
  ASSERT_EQ(cylinder_faces(part), 2);
  // The top face's inner loop: the circle in two arcs.
  int top_edges = 0;
  for (TopExp_Explorer e(part, TopAbs_FACE); e.More(); e.Next()) {
    BRepAdaptor_Surface s(TopoDS::Face(e.Current()));
    if (s.GetType() == GeomAbs_Plane && std::abs(s.Plane().Location().Z() - 20) < 1e-9) {
      for (TopExp_Explorer k(e.Current(), TopAbs_EDGE); k.More(); k.Next()) ++top_edges;
    }
  }
  EXPECT_GE(top_edges, 6);  // 4 sides and at least 2 arcs

  const pr::Part read = pr::read_brep_file(written(part, "split_pocket.stp"));
  const auto pockets = of_kind(read, pr::FeatureKind::ClosedPocket);
  ASSERT_EQ(pockets.size(), 1u);
  const auto& p = *pockets[0];
  EXPECT_EQ(p.outline, pr::Outline::Circle);
  EXPECT_NEAR(p.diameter, 40, 1e-6);
  EXPECT_NEAR(p.depth, 8, 1e-6);
  EXPECT_NEAR(p.placement.location.x, 50, 1e-6);
  EXPECT_NEAR(p.placement.location.y, 40, 1e-6);
  EXPECT_NEAR(p.placement.location.z, 20, 1e-6);
  EXPECT_NE(p.source.find("faces"), std::string::npos) << p.source;  // more than one face
  EXPECT_TRUE(of_kind(read, pr::FeatureKind::RoundHole).empty());
}

TEST(BuiltParts, AHoleInAPocketFloorIsAPocketAndAHole) {
  TopoDS_Shape part = BRepAlgoAPI_Cut(block(), tool(50, 40, 20, 12)).Shape();
  part = BRepAlgoAPI_Cut(part, tool(50, 40, 4, -5)).Shape();
  const pr::Part read = pr::read_brep_file(written(part, "pocket_and_hole.stp"));
  const auto pockets = of_kind(read, pr::FeatureKind::ClosedPocket);
  const auto holes = of_kind(read, pr::FeatureKind::RoundHole);
  ASSERT_EQ(pockets.size(), 1u);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_NEAR(pockets[0]->diameter, 40, 1e-6);
  EXPECT_NEAR(pockets[0]->depth, 8, 1e-6);
  EXPECT_NEAR(holes[0]->diameter, 8, 1e-6);
  EXPECT_NEAR(holes[0]->placement.location.z, 12, 1e-6);  // it starts at the pocket's floor
  EXPECT_NEAR(holes[0]->depth, 12, 1e-6);
  EXPECT_EQ(holes[0]->bottom, pr::HoleBottom::Through);
  EXPECT_TRUE(read.compounds.empty());
}

TEST(BuiltParts, RoundedRectangularPocketWithAHoleInItsFloor) {
  TopoDS_Shape cutter = BRepPrimAPI_MakeBox(gp_Pnt(20, 25, 10), 50, 30, 20).Shape();
  BRepFilletAPI_MakeFillet fillet(cutter);
  for (TopExp_Explorer e(cutter, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge)), b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
    if (std::abs(a.X() - b.X()) < 1e-9 && std::abs(a.Y() - b.Y()) < 1e-9) fillet.Add(6, edge);  // the vertical edges
  }
  TopoDS_Shape part = BRepAlgoAPI_Cut(block(), fillet.Shape()).Shape();
  part = BRepAlgoAPI_Cut(part, tool(30, 40, 3, -5)).Shape();
  const pr::Part read = pr::read_brep_file(written(part, "rounded_pocket.stp"));
  const auto pockets = of_kind(read, pr::FeatureKind::ClosedPocket);
  ASSERT_EQ(pockets.size(), 1u);
  const auto& p = *pockets[0];
  EXPECT_EQ(p.outline, pr::Outline::Rectangle);
  EXPECT_NEAR(p.length, 50, 1e-6);
  EXPECT_NEAR(p.width, 30, 1e-6);
  EXPECT_NEAR(p.corner_radius, 6, 1e-6);
  EXPECT_NEAR(p.depth, 10, 1e-6);
  EXPECT_NEAR(p.placement.location.x, 45, 1e-6);
  EXPECT_NEAR(p.placement.location.y, 40, 1e-6);
  const auto holes = of_kind(read, pr::FeatureKind::RoundHole);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_NEAR(holes[0]->placement.location.z, 10, 1e-6);
}

TEST(BuiltParts, DrillPointsAndACountersink) {
  // A blind hole of 10 with a 118 degree point; a through hole of 6 with a 90 degree countersink of 12.
  const double tip = 5 / std::tan(59 * M_PI / 180);
  TopoDS_Shape drill = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(25, 40, 8), gp_Dir(0, 0, 1)), 5, 20).Shape();
  drill = BRepAlgoAPI_Fuse(drill, BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(25, 40, 8 - tip), gp_Dir(0, 0, 1)), 0, 5, tip).Shape()).Shape();
  TopoDS_Shape part = BRepAlgoAPI_Cut(block(), drill).Shape();
  TopoDS_Shape sink = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(75, 40, 17), gp_Dir(0, 0, 1)), 3, 9, 6).Shape();  // 45 deg: 6 -> 18 wide
  sink = BRepAlgoAPI_Fuse(sink, tool(75, 40, 3, -5)).Shape();
  part = BRepAlgoAPI_Cut(part, sink).Shape();
  const pr::Part read = pr::read_brep_file(written(part, "points_and_countersink.stp"));
  const auto holes = of_kind(read, pr::FeatureKind::RoundHole);
  ASSERT_EQ(holes.size(), 3u);
  const pr::Feature* blind = nullptr;
  const pr::Feature* cone = nullptr;
  const pr::Feature* through = nullptr;
  for (const auto* h : holes) {
    if (std::abs(h->diameter - 10) < 1e-6) blind = h;
    if (h->bottom == pr::HoleBottom::Through) through = h;
    if (std::abs(h->diameter - 12) < 1e-6) cone = h;
  }
  ASSERT_TRUE(blind && cone && through);
  EXPECT_EQ(blind->bottom, pr::HoleBottom::Conical);
  EXPECT_NEAR(blind->tip_angle, 118, 1e-6);
  EXPECT_NEAR(blind->depth, 12 + tip, 1e-6);  // to the point
  EXPECT_EQ(cone->bottom, pr::HoleBottom::Conical);
  EXPECT_NEAR(cone->tip_angle, 90, 1e-6);
  EXPECT_NEAR(cone->depth, 3, 1e-6);
  EXPECT_NEAR(through->diameter, 6, 1e-6);
  EXPECT_NEAR(through->placement.location.z, 17, 1e-6);  // below the countersink
  ASSERT_EQ(read.compounds.size(), 1u);
  EXPECT_EQ(read.compounds[0].kind, pr::CompoundKind::Countersink);
}

TEST(BuiltParts, APocketWithAnIslandIsSaidOnceWithItsFacesAndNotPlanned) {
  // A pocket 60 x 40, 8 deep, with a round boss R8 left standing in it, up to the top.
  TopoDS_Shape part = BRepAlgoAPI_Cut(block(), BRepPrimAPI_MakeBox(gp_Pnt(20, 20, 12), 60, 40, 20).Shape()).Shape();
  part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(50, 40, 12), gp_Dir(0, 0, 1)), 8, 8).Shape()).Shape();
  const pr::Part read = pr::read_brep_file(written(part, "pocket_with_island.stp"));
  // Planned without its island, the pocket's program would mill the boss away: it is left out.
  EXPECT_TRUE(of_kind(read, pr::FeatureKind::ClosedPocket).empty());
  std::vector<std::string> islands;
  for (const auto& w : read.warnings) {
    if (w.message.find("island") != std::string::npos) islands.push_back(w.message);
  }
  ASSERT_EQ(islands.size(), 1u);
  EXPECT_TRUE(islands[0].starts_with("an island (boss, face")) << islands[0];
  EXPECT_NE(islands[0].find("not planned"), std::string::npos) << islands[0];
  EXPECT_TRUE(of_kind(read, pr::FeatureKind::RoundHole).empty());
}

TEST(BuiltParts, AStepFileWithoutASolidIsAnError) {
  const TopoDS_Shape face = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 0, 10, 0, 10).Shape();
  const fs::path file = written(face, "just_a_face.stp");
  try {
    pr::read_part_file(file);
    FAIL() << "read a part from a face";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.where().file, file.string());
    EXPECT_NE(std::string(e.what()).find("no solid"), std::string::npos) << e.what();
  }
}

TEST(BuiltParts, NotAStepFileIsLocated) {
  const fs::path file = fs::temp_directory_path() / "ncbridge_built_parts" / "program.nc";
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "G0 X10 Y10\nM30\n";
  try {
    pr::read_part_file(file);
    FAIL() << "read a program as a part";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.where().line, 1u) << e.what();
  }
}

TEST(BuiltParts, AFileInMetresIsReadInMillimetres) {
  // The part a thousand times smaller, written in millimetres, then its unit made the metre: the
  // file a CAD system working in metres writes (100 mm as 0.1).
  gp_Trsf to_metres;
  to_metres.SetScale(gp_Pnt(0, 0, 0), 0.001);
  const TopoDS_Shape part = BRepBuilderAPI_Transform(BRepAlgoAPI_Cut(block(), tool(30, 40, 5, -5)).Shape(), to_metres).Shape();
  const fs::path file = written(part, "block_in_metres.stp");
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string mm = "SI_UNIT(.MILLI.,.METRE.)";
  const auto at = text.find(mm);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, mm.size(), "SI_UNIT($,.METRE.)");
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  ASSERT_NE(text.find("(0.1,"), std::string::npos) << "100 mm written as 0.1";

  const pr::Part read = pr::read_brep_file(file);
  EXPECT_EQ(read.file_units, "m");
  ASSERT_TRUE(read.bounds);
  EXPECT_NEAR(read.bounds->max[0], 100, 1e-6);
  EXPECT_NEAR(read.bounds->max[2], 20, 1e-6);
  const auto holes = of_kind(read, pr::FeatureKind::RoundHole);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_NEAR(holes[0]->diameter, 10, 1e-6);
  EXPECT_NEAR(holes[0]->depth, 20, 1e-6);
  EXPECT_NEAR(holes[0]->placement.location.x, 30, 1e-6);
  EXPECT_EQ(holes[0]->bottom, pr::HoleBottom::Through);
}
