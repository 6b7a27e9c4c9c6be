// The AP224 reader on the RAMP file (inches, a turned part with holes, a counterbore and turning
// features) and on our own AP224 files (tests/part_reader/data/make_ap224.py): the paper's block
// with a through hole and a slot, and a plate with the other milling features. Expected values
// are the file's numbers (times 25.4 for inches).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ncbridge/common/error.hpp"
#include "ncbridge/part_reader/ap224_reader.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"

namespace pr = ncbridge::part_reader;
namespace fs = std::filesystem;

namespace {

const fs::path kRamp = fs::path(NCBRIDGE_SHARED_DIR) / "corpus" / "ap224" / "ramp_ap224_995277945.stp";
const fs::path kData = fs::path(NCBRIDGE_SOURCE_DIR) / "tests" / "part_reader" / "data";
constexpr double kInch = 25.4;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

pr::Part read_text(const std::string& text, const pr::ReadOptions& options = {}) {
  const auto read = ncbridge::step_writer::part21::read_part21(text, "test.stp");
  return pr::read_ap224(read.graph, "test.stp", options);
}

const pr::Feature& by_source(const pr::Part& part, const std::string& source) {
  for (const auto& f : part.features) {
    if (f.source == source) return f;
  }
  throw std::runtime_error("no feature " + source);
}

const pr::ListedFeature& listed(const pr::Part& part, const std::string& source) {
  for (const auto& l : part.listed) {
    if (l.source == source) return l;
  }
  throw std::runtime_error("nothing listed from " + source);
}

double number_of(const pr::ListedFeature& l, const std::string& name) {
  for (const auto& p : l.parameters) {
    if (p.name == name) return std::stod(p.value);
  }
  throw std::runtime_error(l.source + " lists no " + name);
}

std::string text_of(const pr::ListedFeature& l, const std::string& name) {
  for (const auto& p : l.parameters) {
    if (p.name == name) return p.value;
  }
  throw std::runtime_error(l.source + " lists no " + name);
}

bool warned(const pr::Part& part, const std::string& where, const std::string& words) {
  for (const auto& w : part.warnings) {
    if (w.where == where && w.message.find(words) != std::string::npos) return true;
  }
  return false;
}

void expect_point(const ncbridge::stepnc::CartesianPoint& p, double x, double y, double z, double tol = 1e-9) {
  EXPECT_NEAR(p.x, x, tol);
  EXPECT_NEAR(p.y, y, tol);
  EXPECT_NEAR(p.z, z, tol);
}

}  // namespace

TEST(Ap224Ramp, UnitsProductAndCylindricalStock) {
  const pr::Part part = pr::read_ap224_file(kRamp);
  EXPECT_EQ(part.format, "AP224");
  EXPECT_EQ(part.file_units, "inch");
  EXPECT_EQ(part.name, "KA571_995277945");
  ASSERT_TRUE(part.stock.has_value());
  EXPECT_EQ(part.stock->shape, pr::StockShape::Cylinder);
  EXPECT_NEAR(part.stock->length, 1.5 * kInch, 1e-9);
  EXPECT_NEAR(part.stock->diameter, 2.38157 * kInch, 1e-9);
  const pr::Box box = pr::bounding_box(*part.stock);
  EXPECT_NEAR(box.min[2], 0, 1e-9);
  EXPECT_NEAR(box.max[2], 38.1, 1e-9);
  EXPECT_NEAR(box.max[0], 2.38157 * kInch / 2, 1e-9);
}

TEST(Ap224Ramp, EveryRoundHoleWithDiameterDepthAndBottom) {
  const pr::Part part = pr::read_ap224_file(kRamp);
  ASSERT_EQ(part.features.size(), 4u);
  for (const auto& f : part.features) EXPECT_EQ(f.kind, pr::FeatureKind::RoundHole);

  const auto& small = by_source(part, "#1864");
  EXPECT_NEAR(small.diameter, 0.77 * kInch, 1e-9);
  EXPECT_NEAR(small.depth, 1.5 * kInch, 1e-9);
  EXPECT_EQ(small.bottom, pr::HoleBottom::Flat);
  const auto& large = by_source(part, "#1918");
  EXPECT_NEAR(large.diameter, 1.116 * kInch, 1e-9);
  EXPECT_NEAR(large.depth, 0.65 * kInch, 1e-9);
  EXPECT_EQ(large.bottom, pr::HoleBottom::Flat);
  ASSERT_TRUE(large.diameter_tolerance.has_value());  // +/- 0.001 in
  EXPECT_NEAR(large.diameter_tolerance->first, 0.001 * kInch, 1e-12);
  EXPECT_NEAR(large.diameter_tolerance->second, -0.001 * kInch, 1e-12);
  EXPECT_FALSE(small.diameter_tolerance.has_value());
  // Both open at z = 0 and go up into the part: the tool comes from -z.
  for (const auto* h : {&small, &large}) {
    expect_point(h->placement.location, 0, 1.914928e-16 * kInch, 0);
    EXPECT_NEAR(h->placement.axis.z, -1, 1e-12);
    EXPECT_FALSE(h->accessible);
  }
  const auto& cross_1 = by_source(part, "#2241");
  const auto& cross_2 = by_source(part, "#2308");
  EXPECT_NEAR(cross_1.diameter, 0.0625 * kInch, 1e-9);
  EXPECT_NEAR(cross_1.depth, 0.541265635583464 * kInch, 1e-9);
  EXPECT_NEAR(cross_2.depth, 0.541265635583466 * kInch, 1e-9);
  expect_point(cross_1.placement.location, 1.065785 * kInch, 0.270632817791732 * kInch, 0.25 * kInch);
  expect_point(cross_2.placement.location, -1.065785 * kInch, 0.270632817791732 * kInch, 0.25 * kInch);
  for (const auto* h : {&cross_1, &cross_2}) {
    EXPECT_EQ(h->bottom, pr::HoleBottom::Through);
    EXPECT_NEAR(h->placement.axis.y, 1, 1e-12);  // drilled along -y from y = +0.27 in
    EXPECT_FALSE(h->accessible);
  }
  EXPECT_TRUE(warned(part, "#1864", "needs a setup with -z up (--setup -z)"));
  EXPECT_TRUE(warned(part, "#2241", "needs a setup with +y up (--setup +y)"));
}

TEST(Ap224Ramp, TheCounterbore) {
  const pr::Part part = pr::read_ap224_file(kRamp);
  ASSERT_EQ(part.compounds.size(), 1u);
  const auto& c = part.compounds.front();
  EXPECT_EQ(c.kind, pr::CompoundKind::Counterbore);
  EXPECT_EQ(c.source, "#1848");
  ASSERT_EQ(c.elements.size(), 2u);
  EXPECT_EQ(part.features[c.elements[0]].source, "#1918");  // the large hole first
  EXPECT_EQ(part.features[c.elements[1]].source, "#1864");
  EXPECT_EQ(part.features[c.elements[0]].compound, 0);
}

TEST(Ap224Ramp, SetupFromBelowMakesTheCounterboreAccessible) {
  const pr::Part part = pr::read_ap224_file(kRamp, {pr::SetupUp::MinusZ, {0, 0, 0}});
  const auto& small = by_source(part, "#1864");
  EXPECT_TRUE(small.accessible);
  EXPECT_NEAR(small.placement.axis.z, 1, 1e-12);
  EXPECT_NEAR(small.placement.location.z, 0, 1e-9);
  const pr::Box box = pr::bounding_box(*part.stock);
  EXPECT_NEAR(box.min[2], -38.1, 1e-9);
  EXPECT_NEAR(box.max[2], 0, 1e-9);
  EXPECT_FALSE(by_source(part, "#2241").accessible);
}

TEST(Ap224Ramp, TurningFeaturesAreListedWithTheirParameters) {
  const pr::Part part = pr::read_ap224_file(kRamp);
  int outer_rounds = 0, grooves = 0, threads = 0, chamfers = 0;
  for (const auto& l : part.listed) {
    outer_rounds += l.entity == "OUTER_ROUND";
    grooves += l.entity == "REVOLVED_PROFILE";
    threads += l.entity == "THREAD";
    chamfers += l.entity == "CHAMFER";
    EXPECT_TRUE(warned(part, l.source, l.reason)) << l.source;
  }
  EXPECT_EQ(outer_rounds, 3);
  EXPECT_EQ(grooves, 2);
  EXPECT_EQ(threads, 1);
  EXPECT_EQ(chamfers, 2);

  const auto& shoulder = listed(part, "#1795");
  EXPECT_EQ(shoulder.name, "outer diameter to shoulder");
  EXPECT_EQ(shoulder.reason, "turning feature: not planned for milling");
  EXPECT_NEAR(number_of(shoulder, "diameter"), 1.875 * kInch, 1e-6);
  const auto& tapered = listed(part, "#2083");
  EXPECT_NEAR(number_of(tapered, "diameter"), 2.381569860407206 * kInch, 1e-6);
  EXPECT_NEAR(number_of(tapered, "length"), 0.092107534898198 * kInch, 1e-6);
  EXPECT_NEAR(number_of(tapered, "TAPER 'angle taper' (reduced size): taper angle"), 60, 1e-9);
  const auto& groove = listed(part, "#2171");
  EXPECT_NEAR(number_of(groove, "radius"), 0.59625 * kInch, 1e-6);
  EXPECT_NEAR(number_of(groove, "SQUARE_U_PROFILE 'sweep': width"), 0.139 * kInch, 1e-6);
  const auto& other_groove = listed(part, "#1978");
  EXPECT_NEAR(number_of(other_groove, "SQUARE_U_PROFILE 'sweep': first angle"), 135, 1e-9);
  const auto& thread = listed(part, "#2440");
  EXPECT_NEAR(number_of(thread, "major diameter"), 1.875 * kInch, 1e-6);
  EXPECT_NEAR(number_of(thread, "number of threads"), 12, 1e-12);
  EXPECT_EQ(text_of(thread, "form"), "UNS");
  EXPECT_EQ(text_of(thread, "hand"), "right");
  EXPECT_EQ(text_of(thread, "fit class"), "2A");
  const auto& chamfer = listed(part, "#2369");
  EXPECT_NEAR(number_of(chamfer, "CHAMFER_OFFSET 'first offset': offset amount"), 0.058 * kInch, 1e-6);
  EXPECT_NEAR(number_of(chamfer, "CHAMFER_OFFSET 'second offset': chamfer angle"), 45, 1e-9);
  // The hexagon is an outside profile without a depth in the file: listed, not guessed.
  const auto& hexagon = listed(part, "#2040");
  EXPECT_EQ(hexagon.entity, "OUTSIDE_PROFILE");
  EXPECT_NEAR(number_of(hexagon, "NGON_CLOSED_PROFILE 'outside boundary' (hex boundary): number of sides"), 6, 1e-12);
}

TEST(Ap224PaperBlock, BlockThroughHoleAndSlot) {
  const pr::Part part = pr::read_ap224_file(kData / "paper_block_ap224.stp");
  EXPECT_EQ(part.name, "PAPER_BLOCK");
  EXPECT_EQ(part.file_units, "mm");
  ASSERT_TRUE(part.stock.has_value());
  EXPECT_EQ(part.stock->shape, pr::StockShape::Block);
  EXPECT_DOUBLE_EQ(part.stock->length, 225);
  EXPECT_DOUBLE_EQ(part.stock->width, 100);
  EXPECT_DOUBLE_EQ(part.stock->height, 12.5);
  ASSERT_EQ(part.features.size(), 2u);

  const auto& hole = part.features[0];
  EXPECT_EQ(hole.kind, pr::FeatureKind::RoundHole);
  EXPECT_DOUBLE_EQ(hole.diameter, 75);
  EXPECT_DOUBLE_EQ(hole.depth, 12.5);
  EXPECT_EQ(hole.bottom, pr::HoleBottom::Through);
  expect_point(hole.placement.location, 62.5, 50, 12.5);
  EXPECT_TRUE(hole.accessible);

  const auto& slot = part.features[1];
  EXPECT_EQ(slot.kind, pr::FeatureKind::Slot);
  EXPECT_DOUBLE_EQ(slot.width, 25);
  EXPECT_DOUBLE_EQ(slot.depth, 12.5);
  EXPECT_DOUBLE_EQ(slot.length, 75);
  EXPECT_EQ(slot.slot_ends[0], pr::SlotEnd::Open);
  EXPECT_EQ(slot.slot_ends[1], pr::SlotEnd::Radiused);
  expect_point(slot.placement.location, 187.5, 50, 12.5);  // the middle of the course, at the top
  EXPECT_NEAR(slot.placement.ref_direction.x, -1, 1e-12);
  EXPECT_NEAR(slot.placement.axis.z, 1, 1e-12);
  EXPECT_TRUE(part.listed.empty());
}

TEST(Ap224MilledPlate, FaceAndPockets) {
  const pr::Part part = pr::read_ap224_file(kData / "milled_plate_ap224.stp");
  EXPECT_EQ(part.file_units, "inch");
  ASSERT_EQ(part.features.size(), 8u);
  const auto& face = part.features[0];
  EXPECT_EQ(face.kind, pr::FeatureKind::PlanarFace);
  EXPECT_NEAR(face.depth, 0.05 * kInch, 1e-9);
  EXPECT_NEAR(face.length, 6 * kInch, 1e-9);
  EXPECT_NEAR(face.width, 4 * kInch, 1e-9);
  expect_point(face.placement.location, 3 * kInch, 2 * kInch, 1.25 * kInch);

  const auto& pocket = part.features[1];
  EXPECT_EQ(pocket.kind, pr::FeatureKind::ClosedPocket);
  EXPECT_EQ(pocket.outline, pr::Outline::Rectangle);
  EXPECT_NEAR(pocket.length, 2 * kInch, 1e-9);
  EXPECT_NEAR(pocket.width, 1.2 * kInch, 1e-9);
  EXPECT_NEAR(pocket.corner_radius, 0.25 * kInch, 1e-9);
  EXPECT_NEAR(pocket.depth, 0.5 * kInch, 1e-9);
  EXPECT_NEAR(pocket.placement.ref_direction.y, 1, 1e-12);  // its length runs along y
  expect_point(pocket.placement.location, 1.5 * kInch, 2 * kInch, 1.2 * kInch);
  EXPECT_FALSE(pocket.through);

  const auto& cutout = part.features[2];
  EXPECT_EQ(cutout.kind, pr::FeatureKind::ClosedPocket);
  EXPECT_EQ(cutout.outline, pr::Outline::Circle);
  EXPECT_NEAR(cutout.diameter, kInch, 1e-9);
  EXPECT_TRUE(cutout.through);

  const auto& open = part.features[3];
  EXPECT_EQ(open.kind, pr::FeatureKind::OpenPocket);
  EXPECT_NEAR(open.depth, 0.3 * kInch, 1e-9);
  expect_point(open.placement.location, 4.25 * kInch, 0.5 * kInch, 1.2 * kInch);
  ASSERT_EQ(open.boundary.size(), 4u);
  int open_edges = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& a = open.boundary[i];
    const auto& b = open.boundary[(i + 1) % 4];
    if (!a.open) continue;
    ++open_edges;
    EXPECT_NEAR(a.y, -0.5 * kInch, 1e-9);  // the edge on the part's y- side
    EXPECT_NEAR(b.y, -0.5 * kInch, 1e-9);
  }
  EXPECT_EQ(open_edges, 1);
}

TEST(Ap224MilledPlate, StepAndHoles) {
  const pr::Part part = pr::read_ap224_file(kData / "milled_plate_ap224.stp");
  const auto& step = part.features[4];
  EXPECT_EQ(step.kind, pr::FeatureKind::Step);
  EXPECT_NEAR(step.width, 0.75 * kInch, 1e-9);
  EXPECT_NEAR(step.depth, 0.45 * kInch, 1e-9);
  EXPECT_NEAR(step.length, 4 * kInch, 1e-9);
  expect_point(step.placement.location, 0.375 * kInch, 2 * kInch, 1.2 * kInch);

  ASSERT_EQ(part.compounds.size(), 1u);
  const auto& cb = part.compounds[0];
  const auto& large = part.features[cb.elements[0]];
  const auto& small = part.features[cb.elements[1]];
  EXPECT_NEAR(large.diameter, 0.5 * kInch, 1e-9);
  EXPECT_NEAR(large.depth, 0.25 * kInch, 1e-9);
  EXPECT_EQ(large.bottom, pr::HoleBottom::Flat);
  EXPECT_NEAR(small.diameter, 0.3125 * kInch, 1e-9);
  EXPECT_EQ(small.bottom, pr::HoleBottom::Through);

  const auto& blind = part.features[7];
  EXPECT_EQ(blind.bottom, pr::HoleBottom::Conical);
  EXPECT_DOUBLE_EQ(blind.tip_angle, 118);
  EXPECT_NEAR(blind.depth, 0.6 * kInch, 1e-9);
}

TEST(Ap224BadInput, DanglingReferenceIsLocated) {
  std::string text = slurp(kData / "paper_block_ap224.stp");
  const std::string from = "SHAPE_DEFINING_RELATIONSHIP('diameter','profile usage',#";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at + from.size(), text.find(',', at + from.size()) - at - from.size(), "9999");
  try {
    read_text(text);
    FAIL() << "read a dangling reference";
  } catch (const ncbridge::InputError& e) {
    EXPECT_EQ(e.where().file, "test.stp");
    EXPECT_GT(e.where().line, 0u);
    EXPECT_NE(std::string(e.what()).find("9999"), std::string::npos) << e.what();
  }
}

TEST(Ap224BadInput, HoleWithoutDiameterNamesTheHole) {
  std::string text = slurp(kData / "paper_block_ap224.stp");
  const std::string item = "REPRESENTATION_ITEM('diameter')";
  const auto at = text.find(item);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, item.size(), "REPRESENTATION_ITEM('radius')");
  try {
    read_text(text);
    FAIL() << "read a hole without a diameter";
  } catch (const ncbridge::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("ROUND_HOLE"), std::string::npos) << what;
    EXPECT_NE(what.find("'diameter'"), std::string::npos) << what;
    // The hole's own line in the file.
    std::istringstream lines(text);
    std::string line;
    std::uint32_t n = 0, hole_line = 0;
    while (std::getline(lines, line)) {
      ++n;
      if (line.find("ROUND_HOLE()") != std::string::npos) hole_line = n;
    }
    EXPECT_EQ(e.where().line, hole_line);
  }
}

TEST(Ap224BadInput, NotAStepFile) {
  EXPECT_THROW(read_text("G0 X10 Y10\nM30\n"), ncbridge::InputError);
}

TEST(Ap224BadInput, UnitLoopIsAnError) {
  std::string text = slurp(kData / "paper_block_ap224.stp");
  // The degree's conversion factor refers back to the degree itself.
  const std::string factor = "PLANE_ANGLE_MEASURE(0.0174532925199433),#2)";
  const auto at = text.find(factor);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, factor.size(), "PLANE_ANGLE_MEASURE(0.0174532925199433),#5)");
  EXPECT_THROW(read_text(text), ncbridge::InputError);
}
