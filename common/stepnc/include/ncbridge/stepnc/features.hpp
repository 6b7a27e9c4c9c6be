#pragma once
// Manufacturing features of ISO 14649-10 (2002 draft). CC1 uses TOOLPATH_FEATURE (placeholder
// for freeform operations) and ROUND_HOLE (canned cycles); the CC2 features (issue 4) are here as
// plain structs so the feature recogniser fills the same model. A feature's its_workpiece is the
// project's workpiece and its its_operations are the operations of the workingsteps naming it:
// both are derived when the model is written, not stored.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ncbridge/stepnc/geometry.hpp"

namespace ncbridge::stepnc {

// TOLERANCED_LENGTH_MEASURE with a PLUS_MINUS_VALUE tolerance.
struct TolerancedLengthMeasure {
  double theoretical_size = 0;
  double upper_limit = 0;
  double lower_limit = 0;
  int significant_digits = 3;
  friend bool operator==(const TolerancedLengthMeasure&, const TolerancedLengthMeasure&) = default;
};

// ---- Hole bottoms
struct ThroughBottomCondition { friend bool operator==(const ThroughBottomCondition&, const ThroughBottomCondition&) = default; };
struct FlatHoleBottom { friend bool operator==(const FlatHoleBottom&, const FlatHoleBottom&) = default; };
struct ConicalHoleBottom {
  double tip_angle = 118;  // degrees
  friend bool operator==(const ConicalHoleBottom&, const ConicalHoleBottom&) = default;
};
using HoleBottomCondition = std::variant<ThroughBottomCondition, FlatHoleBottom, ConicalHoleBottom>;

// ---- Profiles and paths (CC2)
struct LinearPath {  // LINEAR_PATH: distance along its_direction
  std::optional<Axis2Placement3d> placement;
  TolerancedLengthMeasure distance;
  Direction its_direction{1, 0, 0};
  friend bool operator==(const LinearPath&, const LinearPath&) = default;
};
struct LinearProfile {  // LINEAR_PROFILE: a straight open profile of profile_length
  std::optional<Axis2Placement3d> placement;
  double profile_length = 0;
  friend bool operator==(const LinearProfile&, const LinearProfile&) = default;
};
struct RectangularClosedProfile {
  std::optional<Axis2Placement3d> placement;
  TolerancedLengthMeasure profile_width, profile_length;
  friend bool operator==(const RectangularClosedProfile&, const RectangularClosedProfile&) = default;
};
struct CircularClosedProfile {
  std::optional<Axis2Placement3d> placement;
  TolerancedLengthMeasure diameter;
  friend bool operator==(const CircularClosedProfile&, const CircularClosedProfile&) = default;
};
struct GeneralClosedProfile {
  std::optional<Axis2Placement3d> placement;
  CompositeCurve closed_profile_shape;
  friend bool operator==(const GeneralClosedProfile&, const GeneralClosedProfile&) = default;
};
struct GeneralProfile {  // an open profile of any shape
  std::optional<Axis2Placement3d> placement;
  CompositeCurve its_profile;
  friend bool operator==(const GeneralProfile&, const GeneralProfile&) = default;
};
using ClosedProfile = std::variant<RectangularClosedProfile, CircularClosedProfile, GeneralClosedProfile>;
using OpenProfile = std::variant<LinearProfile, GeneralProfile>;

struct PlanarPocketBottomCondition { friend bool operator==(const PlanarPocketBottomCondition&, const PlanarPocketBottomCondition&) = default; };
struct ThroughPocketBottomCondition { friend bool operator==(const ThroughPocketBottomCondition&, const ThroughPocketBottomCondition&) = default; };
using PocketBottomCondition = std::variant<PlanarPocketBottomCondition, ThroughPocketBottomCondition>;

// ---- Features. Every MACHINING_FEATURE has an id, a placement and a depth plane (in the
// placement's frame: a plane at z = -depth below the placement).
struct MachiningFeature {
  std::string its_id;
  Axis2Placement3d feature_placement;
  Plane depth;
  friend bool operator==(const MachiningFeature&, const MachiningFeature&) = default;
};

struct ToolpathFeature : MachiningFeature {
  friend bool operator==(const ToolpathFeature&, const ToolpathFeature&) = default;
};

struct RoundHole : MachiningFeature {
  TolerancedLengthMeasure diameter;
  HoleBottomCondition bottom_condition = FlatHoleBottom{};
  friend bool operator==(const RoundHole&, const RoundHole&) = default;
};

struct PlanarFace : MachiningFeature {
  LinearPath course_of_travel;
  LinearProfile removal_boundary;
  std::optional<ClosedProfile> face_boundary;
  friend bool operator==(const PlanarFace&, const PlanarFace&) = default;
};

struct ClosedPocket : MachiningFeature {
  std::optional<double> slope;
  PocketBottomCondition bottom_condition = PlanarPocketBottomCondition{};
  std::optional<TolerancedLengthMeasure> planar_radius, orthogonal_radius;
  ClosedProfile feature_boundary = RectangularClosedProfile{};
  friend bool operator==(const ClosedPocket&, const ClosedPocket&) = default;
};

struct OpenPocket : MachiningFeature {
  std::optional<double> slope;
  PocketBottomCondition bottom_condition = PlanarPocketBottomCondition{};
  std::optional<TolerancedLengthMeasure> planar_radius, orthogonal_radius;
  OpenProfile open_boundary = LinearProfile{};
  std::optional<OpenProfile> wall_boundary;
  friend bool operator==(const OpenPocket&, const OpenPocket&) = default;
};

enum class SlotEndType : std::uint8_t { Open, Flat, Radiused, Loop, Woodruff };
struct Slot : MachiningFeature {
  LinearPath course_of_travel;  // CC2 recognises straight slots; other travel paths come later
  OpenProfile swept_shape = LinearProfile{};
  std::vector<SlotEndType> end_conditions;  // 0..2
  friend bool operator==(const Slot&, const Slot&) = default;
};

struct Step : MachiningFeature {
  LinearPath open_boundary;
  friend bool operator==(const Step&, const Step&) = default;
};

struct GeneralOutsideProfile : MachiningFeature {
  LinearPath profile_swept_shape;
  CompositeCurve feature_boundary;  // as a GENERAL_CLOSED_PROFILE / GENERAL_PROFILE
  bool closed = true;
  friend bool operator==(const GeneralOutsideProfile&, const GeneralOutsideProfile&) = default;
};

// REGION (a freeform area; placement optional in the schema, kept here as the bounding frame),
// written as its subtype REGION_PROJECTION: the area's outline projected along proj_dir down to
// `depth` below the placement.
struct Region {
  std::string its_id;
  std::optional<Axis2Placement3d> feature_placement;
  CompositeCurve proj_curve;
  Direction proj_dir{0, 0, -1};
  TolerancedLengthMeasure depth;
  friend bool operator==(const Region&, const Region&) = default;
};

using Feature = std::variant<ToolpathFeature, RoundHole, PlanarFace, ClosedPocket, OpenPocket,
                             Slot, Step, GeneralOutsideProfile, Region>;

const std::string& feature_id(const Feature& feature);
std::string_view entity_name(const Feature& feature);  // "ROUND_HOLE", ...

}  // namespace ncbridge::stepnc
