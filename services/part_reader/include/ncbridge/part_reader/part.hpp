#pragma once
// What the part_reader reads from a STEP part: the machining features of the part (ISO 14649
// kinds: planar face, round hole, closed and open pocket, slot, step, general outside profile),
// the counterbores and countersinks they form, the stock, and what it lists but does not plan
// (turning features, features facing another way than the setup). Lengths are millimetres and
// everything is in the setup frame: z up, the spindle's side (see ReadOptions).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ncbridge/stepnc/geometry.hpp"

namespace ncbridge::part_reader {

struct Point2 {
  double x = 0, y = 0;
  friend bool operator==(const Point2&, const Point2&) = default;
};

// One corner of a closed outline and the edge that leaves it: a straight edge when bulge is 0,
// else an arc to the next corner with bulge = tan(swept angle / 4), positive counter-clockwise.
struct OutlineVertex {
  double x = 0, y = 0;
  double bulge = 0;
  bool open = false;  // the edge leaving this corner is open to the outside (open pockets, steps)
  friend bool operator==(const OutlineVertex&, const OutlineVertex&) = default;
};

enum class FeatureKind : std::uint8_t {
  PlanarFace, RoundHole, ClosedPocket, OpenPocket, Slot, Step, GeneralOutsideProfile
};

// ISO 14649 hole bottom conditions (through_bottom_condition and the blind_bottom_condition
// subtypes).
enum class HoleBottom : std::uint8_t { Through, Flat, Conical, FlatWithRadius, Spherical };

enum class Outline : std::uint8_t { None, Rectangle, Circle, General };

enum class SlotEnd : std::uint8_t { Open, Radiused, Flat };

// A side of the part, in the setup frame.
enum class Side : std::uint8_t { XMinus, XPlus, YMinus, YPlus };

struct Feature {
  FeatureKind kind = FeatureKind::RoundHole;
  std::string source;  // where it was read: "#1864" (AP224 instance), "faces 10, 24" (B-rep)
  std::string name;    // the file's own name for it, when it has one
  std::uint32_t line = 0;  // the line of the file that defines it (AP224 instances), 0 when none
  // ISO 14649 placement: the origin at the feature's top (a hole's axis where it opens, a
  // pocket's or profile's outline centre, a slot's start), z pointing out of the material (the
  // side the tool comes from), x along the feature's length.
  stepnc::Axis2Placement3d placement;
  double depth = 0;  // from the placement down -z to the floor (a through feature: to where the part ends)

  // Round holes.
  double diameter = 0;
  HoleBottom bottom = HoleBottom::Flat;
  double tip_angle = 0;      // Conical: the included angle in degrees (118 for a twist drill's point)
  double bottom_radius = 0;  // FlatWithRadius, Spherical
  // The diameter's tolerance as the file gives it (upper and lower deviation, mm); B-rep files
  // carry none.
  std::optional<std::pair<double, double>> diameter_tolerance;

  // Outline in the placement's xy plane: Rectangle (length along x, width along y, centred on
  // the origin), Circle (diameter), General (`boundary`, closed, counter-clockwise).
  Outline outline = Outline::None;
  double length = 0;
  double width = 0;
  double corner_radius = 0;  // the vertical corners of a rectangle (ISO orthogonal_radius)
  double floor_radius = 0;   // the fillet between walls and floor (ISO planar_radius)
  std::vector<OutlineVertex> boundary;
  bool through = false;      // a pocket or slot cut through the part (no floor)
  std::vector<Side> open_sides;

  // Slots: `length` is the course of travel (from end centre to end centre: an open end lies on
  // the part's outline), `width` across it, the ends in course order.
  std::array<SlotEnd, 2> slot_ends{SlotEnd::Open, SlotEnd::Open};

  int compound = -1;        // index into Part::compounds, or -1
  bool accessible = true;   // its z is the setup's +Z; otherwise listed with a warning, not planned
};

enum class CompoundKind : std::uint8_t { Counterbore, Countersink };

// ISO 14649 counterbore_hole / countersunk_hole: round holes on one axis, outermost first.
struct Compound {
  CompoundKind kind = CompoundKind::Counterbore;
  std::string source;
  std::vector<std::size_t> elements;  // indices into Part::features
};

struct Parameter {
  std::string name;   // as the file names it ("diameter", "taper angle", "hand")
  std::string value;  // the number in mm or degrees, or the text
  friend bool operator==(const Parameter&, const Parameter&) = default;
};

// A feature read but not planned for milling (turning features, features of kinds this reader
// does not map), with its parameters and the reason.
struct ListedFeature {
  std::string entity;  // "OUTER_ROUND", "THREAD", ...
  std::string name;
  std::string source;
  std::vector<Parameter> parameters;
  std::string reason;
};

enum class StockShape : std::uint8_t { Block, Cylinder };

// A stock the file defines (AP224 block_shape_representation / cylindrical_shape_representation).
struct PartStock {
  StockShape shape = StockShape::Block;
  stepnc::Axis2Placement3d placement;  // block: a corner, edges along x, y, z; cylinder: the axis' start
  double length = 0, width = 0, height = 0;  // block along x, y, z; cylinder: length along z
  double diameter = 0;
  std::string source;
};

struct Box {
  std::array<double, 3> min{0, 0, 0};
  std::array<double, 3> max{0, 0, 0};
  friend bool operator==(const Box&, const Box&) = default;
};

struct Warning {
  std::string where;  // "#2241", "faces 12, 13", or empty
  std::string message;
};

struct Part {
  std::string name;        // the product's id, or the file's stem
  std::string file;
  std::string format;      // "AP224", "AP203", "AP214", "AP242"
  std::string file_units;  // the file's length unit: "mm", "inch", "m", ...
  std::optional<PartStock> stock;  // the file's own
  std::optional<Box> bounds;       // the solid's axis-aligned box (B-rep parts)
  // B-rep parts: the outline seen from above (the outer loop of the faces the part stands on,
  // setup XY, counter-clockwise) and the heights of its top and bottom. The stock-dependent
  // features (the top face to mill, the outside profile) come from these: add_stock_features.
  std::vector<OutlineVertex> footprint;
  double top_z = 0, bottom_z = 0;
  std::vector<Feature> features;
  std::vector<Compound> compounds;
  std::vector<ListedFeature> listed;
  std::vector<Warning> warnings;
};

// The part's side facing the spindle in the setup: the setup frame is the part frame turned so
// that this side is +Z, then moved by the offset.
enum class SetupUp : std::uint8_t { PlusZ, MinusZ, PlusX, MinusX, PlusY, MinusY };

struct ReadOptions {
  SetupUp up = SetupUp::PlusZ;
  std::array<double, 3> offset{0, 0, 0};  // mm, added after the turn
};

// The axis-aligned box around a stock (a cylinder's box when it is one).
Box bounding_box(const PartStock& stock);

// For a B-rep part cut from `stock` (setup frame): the planar face that mills the stock's top
// down to the part's top, and the general outside profile when the stock reaches beyond the
// part's outline. Both come first in Part::features. No-op for parts without a footprint.
void add_stock_features(Part& part, const Box& stock);

std::string_view to_string(FeatureKind kind);  // the ISO 14649 entity name in lower case
std::string_view to_string(HoleBottom bottom);  // "through", "flat", "conical", ...
std::string_view to_string(SlotEnd end);
std::string_view to_string(Side side);          // "x-", "x+", "y-", "y+"
std::string_view to_string(SetupUp up);         // "+z", "-z", ...
std::optional<SetupUp> setup_up_from_string(std::string_view text);
std::string_view to_string(CompoundKind kind);  // "counterbore", "countersink"

}  // namespace ncbridge::part_reader
