#pragma once
// Internal to ncbridge_stepnc_codec: the model's fields and the byte Encoder / Decoder.
// One description of each entity's fields, `fields(ar, value)`, serves both directions: the
// Encoder appends what it is given, the Decoder fills what it is given. A field added to the
// model and not here makes the round-trip tests fail (they compare whole projects with ==).
#include "ncbridge/stepnc/project.hpp"

#include <bit>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "ncbridge/common/error.hpp"

namespace ncbridge::stepnc_codec::detail {

using namespace ncbridge::stepnc;

constexpr std::uint32_t kVersion = 3;  // 2: REGION carries its projection; 3: B-splines, workpiece probing

// S is T, possibly const: the same fields() serves encoding (const) and decoding.
template <class S, class T>
concept Is = std::same_as<std::remove_const_t<S>, T>;

// How many enumerators each model enum has (decoding rejects the rest).
template <class E> constexpr std::uint8_t enum_count = 0;
template <> constexpr std::uint8_t enum_count<ToolpathType> = 6;
template <> constexpr std::uint8_t enum_count<CutmodeType> = 2;
template <> constexpr std::uint8_t enum_count<RotDirection> = 2;
template <> constexpr std::uint8_t enum_count<LeftOrRight> = 2;
template <> constexpr std::uint8_t enum_count<SlotEndType> = 5;
template <> constexpr std::uint8_t enum_count<ToolBody> = 12;
template <> constexpr std::uint8_t enum_count<Hand> = 3;
template <> constexpr std::uint8_t enum_count<ToolReferencePoint> = 2;
template <> constexpr std::uint8_t enum_count<KnotType> = 4;

// ---- Geometry
template <class Ar, Is<CartesianPoint> S> void fields(Ar& ar, S& v) { ar(v.x, v.y, v.z); }
template <class Ar, Is<Direction> S> void fields(Ar& ar, S& v) { ar(v.x, v.y, v.z); }
template <class Ar, Is<Axis2Placement3d> S> void fields(Ar& ar, S& v) { ar(v.location, v.axis, v.ref_direction); }
template <class Ar, Is<stepnc::Plane> S> void fields(Ar& ar, S& v) { ar(v.position); }
template <class Ar, Is<Block> S> void fields(Ar& ar, S& v) { ar(v.position, v.x, v.y, v.z); }
template <class Ar, Is<Polyline> S> void fields(Ar& ar, S& v) { ar(v.points); }
template <class Ar, Is<TrimmedCircle> S> void fields(Ar& ar, S& v) {
  ar(v.position, v.radius, v.trim_1_point, v.trim_1_parameter, v.trim_2_point, v.trim_2_parameter, v.sense_agreement);
}
template <class Ar, Is<BSplineCurve> S> void fields(Ar& ar, S& v) {
  ar(v.degree, v.control_points, v.knot_multiplicities, v.knots, v.knot_spec, v.weights);
}
template <class Ar, Is<CompositeCurve> S> void fields(Ar& ar, S& v) { ar(v.segments); }
template <class Ar, class Tag> void fields(Ar& ar, Ref<Tag>& v) { ar(v.index); }
template <class Ar, class Tag> void fields(Ar& ar, const Ref<Tag>& v) { ar(v.index); }

// ---- Features
template <class Ar, Is<TolerancedLengthMeasure> S> void fields(Ar& ar, S& v) {
  ar(v.theoretical_size, v.upper_limit, v.lower_limit, v.significant_digits);
}
template <class Ar, Is<ThroughBottomCondition> S> void fields(Ar&, S&) {}
template <class Ar, Is<FlatHoleBottom> S> void fields(Ar&, S&) {}
template <class Ar, Is<ConicalHoleBottom> S> void fields(Ar& ar, S& v) { ar(v.tip_angle); }
template <class Ar, Is<LinearPath> S> void fields(Ar& ar, S& v) { ar(v.placement, v.distance, v.its_direction); }
template <class Ar, Is<LinearProfile> S> void fields(Ar& ar, S& v) { ar(v.placement, v.profile_length); }
template <class Ar, Is<RectangularClosedProfile> S> void fields(Ar& ar, S& v) {
  ar(v.placement, v.profile_width, v.profile_length);
}
template <class Ar, Is<CircularClosedProfile> S> void fields(Ar& ar, S& v) { ar(v.placement, v.diameter); }
template <class Ar, Is<GeneralClosedProfile> S> void fields(Ar& ar, S& v) { ar(v.placement, v.closed_profile_shape); }
template <class Ar, Is<GeneralProfile> S> void fields(Ar& ar, S& v) { ar(v.placement, v.its_profile); }
template <class Ar, Is<PlanarPocketBottomCondition> S> void fields(Ar&, S&) {}
template <class Ar, Is<ThroughPocketBottomCondition> S> void fields(Ar&, S&) {}
template <class Ar, Is<MachiningFeature> S> void fields(Ar& ar, S& v) { ar(v.its_id, v.feature_placement, v.depth); }

template <class Base, class S>
auto& base(S& v) {
  if constexpr (std::is_const_v<S>) return static_cast<const Base&>(v);
  else return static_cast<Base&>(v);
}

template <class Ar, Is<ToolpathFeature> S> void fields(Ar& ar, S& v) { ar(base<MachiningFeature>(v)); }
template <class Ar, Is<RoundHole> S> void fields(Ar& ar, S& v) {
  ar(base<MachiningFeature>(v), v.diameter, v.bottom_condition);
}
template <class Ar, Is<PlanarFace> S> void fields(Ar& ar, S& v) {
  ar(base<MachiningFeature>(v), v.course_of_travel, v.removal_boundary, v.face_boundary);
}
template <class Ar, Is<ClosedPocket> S> void fields(Ar& ar, S& v) {
  ar(base<MachiningFeature>(v), v.slope, v.bottom_condition, v.planar_radius, v.orthogonal_radius, v.feature_boundary);
}
template <class Ar, Is<OpenPocket> S> void fields(Ar& ar, S& v) {
  ar(base<MachiningFeature>(v), v.slope, v.bottom_condition, v.planar_radius, v.orthogonal_radius, v.open_boundary,
     v.wall_boundary);
}
template <class Ar, Is<Slot> S> void fields(Ar& ar, S& v) {
  ar(base<MachiningFeature>(v), v.course_of_travel, v.swept_shape, v.end_conditions);
}
template <class Ar, Is<Step> S> void fields(Ar& ar, S& v) { ar(base<MachiningFeature>(v), v.open_boundary); }
template <class Ar, Is<GeneralOutsideProfile> S> void fields(Ar& ar, S& v) {
  ar(base<MachiningFeature>(v), v.profile_swept_shape, v.feature_boundary, v.closed);
}
template <class Ar, Is<Region> S> void fields(Ar& ar, S& v) {
  ar(v.its_id, v.feature_placement, v.proj_curve, v.proj_dir, v.depth);
}

// ---- Operations
template <class Ar, Is<CutterLocationTrajectory> S> void fields(Ar& ar, S& v) {
  ar(v.its_priority, v.its_type, v.its_technology, v.its_machine_functions, v.its_direction, v.basiccurve);
}
template <class Ar, Is<ToolpathList> S> void fields(Ar& ar, S& v) { ar(v.its_list); }
template <class Ar, Is<MachiningOperation> S> void fields(Ar& ar, S& v) {
  ar(v.its_toolpath, v.its_id, v.retract_plane, v.start_point, v.its_tool, v.its_technology, v.its_machine_functions,
     v.overcut_length);
}
template <class Ar, Is<FreeformOperation> S> void fields(Ar& ar, S& v) { ar(base<MachiningOperation>(v)); }
template <class Ar, Is<Unidirectional> S> void fields(Ar& ar, S& v) { ar(v.feed_direction, v.cutmode); }
template <class Ar, Is<Bidirectional> S> void fields(Ar& ar, S& v) { ar(v.feed_direction, v.stepover_direction); }
template <class Ar, Is<ContourParallel> S> void fields(Ar& ar, S& v) { ar(v.rotation_direction, v.cutmode); }
template <class Ar, Is<ContourSpiral> S> void fields(Ar& ar, S& v) { ar(v.rotation_direction, v.cutmode); }
template <class Ar, Is<CenterMilling> S> void fields(Ar&, S&) {}
// PLANE_ROUGH_MILLING ... BOTTOM_AND_SIDE_FINISH_MILLING add nothing to TWO5D_MILLING_OPERATION.
template <class Ar, std::derived_from<Two5DMillingOperation> S>
void fields(Ar& ar, S& v) {
  ar(base<MachiningOperation>(v), v.its_machining_strategy, v.axial_cutting_depth, v.radial_cutting_depth,
     v.allowance_side, v.allowance_bottom);
}
template <class Ar, Is<DrillingTypeStrategy> S> void fields(Ar& ar, S& v) {
  ar(v.reduced_cut_at_start, v.reduced_feed_at_start, v.depth_of_start, v.reduced_cut_at_end, v.reduced_feed_at_end,
     v.depth_of_end);
}
template <class Ar, Is<DrillingTypeOperation> S> void fields(Ar& ar, S& v) {
  ar(base<MachiningOperation>(v), v.cutting_depth, v.previous_diameter, v.dwell_time_bottom, v.feed_on_retract,
     v.its_machining_strategy);
}
template <class Ar, Is<Drilling> S> void fields(Ar& ar, S& v) { ar(base<DrillingTypeOperation>(v)); }
template <class Ar, Is<CenterDrilling> S> void fields(Ar& ar, S& v) { ar(base<DrillingTypeOperation>(v)); }
template <class Ar, Is<BackBoring> S> void fields(Ar& ar, S& v) { ar(base<DrillingTypeOperation>(v)); }
template <class Ar, Is<MultistepDrilling> S> void fields(Ar& ar, S& v) {
  ar(base<DrillingTypeOperation>(v), v.retract_distance, v.first_depth, v.depth_of_step, v.dwell_time_step);
}
template <class Ar, Is<BoringOperation> S> void fields(Ar& ar, S& v) {
  ar(base<DrillingTypeOperation>(v), v.spindle_stop_at_bottom, v.depth_of_testcut, v.waiting_position);
}
template <class Ar, Is<Boring> S> void fields(Ar& ar, S& v) { ar(base<BoringOperation>(v)); }
template <class Ar, Is<Reaming> S> void fields(Ar& ar, S& v) { ar(base<BoringOperation>(v)); }
template <class Ar, Is<Tapping> S> void fields(Ar& ar, S& v) { ar(base<DrillingTypeOperation>(v), v.compensation_chuck); }

// ---- Resources
template <class Ar, Is<MillingToolDimension> S> void fields(Ar& ar, S& v) {
  ar(v.diameter, v.tool_tip_half_angle, v.tool_circumference_angle, v.cutting_edge_length, v.edge_radius,
     v.edge_center_vertical, v.edge_center_horizontal);
}
template <class Ar, Is<MillingCuttingTool> S> void fields(Ar& ar, S& v) {
  ar(v.its_id, v.number, v.body, v.dimension, v.number_of_teeth, v.hand_of_cut, v.coolant_through_tool, v.pilot_length,
     v.tool_offset_length, v.overall_assembly_length);
}
template <class Ar, Is<MillingTechnology> S> void fields(Ar& ar, S& v) {
  ar(v.feedrate, v.feedrate_reference, v.cutspeed, v.spindle, v.feedrate_per_tooth, v.synchronize_spindle_with_feed,
     v.inhibit_feedrate_override, v.inhibit_spindle_override);
}
template <class Ar, Is<MillingMachineFunctions> S> void fields(Ar& ar, S& v) {
  ar(v.coolant, v.coolant_pressure, v.mist, v.through_spindle_coolant, v.through_pressure, v.chip_removal);
}

// ---- Project
template <class Ar, Is<SourceLines> S> void fields(Ar& ar, S& v) { ar(v.file, v.first_line, v.last_line); }
template <class Ar, Is<MachiningWorkingstep> S> void fields(Ar& ar, S& v) {
  ar(v.its_id, v.its_secplane, v.its_feature, v.its_operation, v.source);
}
template <class Ar, Is<RapidMovement> S> void fields(Ar& ar, S& v) { ar(v.its_id, v.its_secplane, v.its_toolpath, v.source); }
template <class Ar, Is<NcVariable> S> void fields(Ar& ar, S& v) { ar(v.its_name, v.initial_value); }
template <class Ar, Is<WorkpieceProbing> S> void fields(Ar& ar, S& v) {
  ar(v.its_id, v.its_secplane, v.measured_offset, v.start_position, v.its_direction, v.expected_value, v.its_probe,
     v.source);
}
template <class Ar, Is<Workplan> S> void fields(Ar& ar, S& v) { ar(v.its_id, v.its_elements); }
template <class Ar, Is<Workpiece> S> void fields(Ar& ar, S& v) {
  ar(v.its_id, v.global_tolerance, v.its_bounding_geometry, v.clamping_positions);
}
template <class Ar, Is<WorkpieceSetup> S> void fields(Ar& ar, S& v) { ar(v.its_origin); }
template <class Ar, Is<Setup> S> void fields(Ar& ar, S& v) { ar(v.its_id, v.its_origin, v.its_secplane, v.its_workpiece_setup); }
template <class Ar, Is<Project> S> void fields(Ar& ar, S& v) {
  ar(v.its_id, v.main_workplan, v.workpiece, v.rawpiece, v.setup, v.tools, v.technologies, v.machine_functions,
     v.features, v.operations);
}

template <class T> struct is_vector : std::false_type {};
template <class T> struct is_vector<std::vector<T>> : std::true_type {};
template <class T> struct is_optional : std::false_type {};
template <class T> struct is_optional<std::optional<T>> : std::true_type {};
template <class T> struct is_variant : std::false_type {};
template <class... T> struct is_variant<std::variant<T...>> : std::true_type {};

class Encoder {
 public:
  explicit Encoder(std::string& out) : out_(out) {}

  template <class... T>
  void operator()(const T&... values) { (one(values), ...); }

 private:
  template <class T>
  void one(const T& v) {
    if constexpr (std::is_same_v<T, bool>) {
      out_.push_back(v ? '\1' : '\0');
    } else if constexpr (std::is_enum_v<T>) {
      out_.push_back(static_cast<char>(v));
    } else if constexpr (std::is_same_v<T, double>) {
      fixed(std::bit_cast<std::uint64_t>(v));
    } else if constexpr (std::is_integral_v<T>) {
      fixed(static_cast<std::uint64_t>(static_cast<std::int64_t>(v)));
    } else if constexpr (std::is_same_v<T, std::string>) {
      fixed(v.size());
      out_.append(v);
    } else if constexpr (is_vector<T>::value) {
      fixed(v.size());
      for (const auto& e : v) one(e);
    } else if constexpr (is_optional<T>::value) {
      out_.push_back(v ? '\1' : '\0');
      if (v) one(*v);
    } else if constexpr (is_variant<T>::value) {
      out_.push_back(static_cast<char>(v.index()));
      std::visit([&](const auto& alt) { one(alt); }, v);
    } else {
      fields(*this, v);
    }
  }

  void fixed(std::uint64_t v) {
    char bytes[8];
    for (int i = 0; i < 8; ++i) bytes[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
    out_.append(bytes, 8);
  }

  std::string& out_;
};

class Decoder {
 public:
  explicit Decoder(std::string_view in) : in_(in) {}

  template <class... T>
  void operator()(T&... values) { (one(values), ...); }

  void expect_end() const {
    if (at_ != in_.size()) fail(std::to_string(in_.size() - at_) + " bytes after the project");
  }
  std::string_view take(std::size_t n) {
    if (n > in_.size() - at_) fail("truncated: " + std::to_string(n) + " bytes wanted, " +
                                   std::to_string(in_.size() - at_) + " left");
    const std::string_view s = in_.substr(at_, n);
    at_ += n;
    return s;
  }
  std::uint64_t fixed() {
    const std::string_view b = take(8);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(b[i])) << (8 * i);
    return v;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError({"<stepnc model>", 0, static_cast<std::uint32_t>(at_ + 1)}, why);
  }

 private:
  std::uint8_t byte() { return static_cast<std::uint8_t>(take(1)[0]); }

  // A sequence of n elements needs at least n bytes: a count beyond the rest is malformed
  // (and never makes us allocate what an attacker asks for).
  std::size_t count() {
    const std::uint64_t n = fixed();
    if (n > in_.size() - at_) fail("count " + std::to_string(n) + " larger than the rest of the bytes");
    return static_cast<std::size_t>(n);
  }

  template <class T>
  void one(T& v) {
    if constexpr (std::is_same_v<T, bool>) {
      const std::uint8_t b = byte();
      if (b > 1) fail("boolean byte " + std::to_string(b));
      v = b == 1;
    } else if constexpr (std::is_enum_v<T>) {
      const std::uint8_t b = byte();
      if (b >= enum_count<T>) fail("enumerator " + std::to_string(b) + " out of range");
      v = static_cast<T>(b);
    } else if constexpr (std::is_same_v<T, double>) {
      v = std::bit_cast<double>(fixed());
    } else if constexpr (std::is_integral_v<T>) {
      const auto wide = static_cast<std::int64_t>(fixed());
      if (!std::in_range<T>(wide)) fail("integer " + std::to_string(wide) + " out of range");
      v = static_cast<T>(wide);
    } else if constexpr (std::is_same_v<T, std::string>) {
      v = std::string(take(count()));
    } else if constexpr (is_vector<T>::value) {
      const std::size_t n = count();
      v.clear();
      v.reserve(n);
      for (std::size_t i = 0; i < n; ++i) one(v.emplace_back());
    } else if constexpr (is_optional<T>::value) {
      bool present = false;
      one(present);
      v.reset();
      if (present) one(v.emplace());
    } else if constexpr (is_variant<T>::value) {
      const std::uint8_t index = byte();
      if (index >= std::variant_size_v<T>) fail("variant alternative " + std::to_string(index) + " out of range");
      alternative(v, index, std::make_index_sequence<std::variant_size_v<T>>());
    } else {
      fields(*this, v);
    }
  }

  template <class V, std::size_t... I>
  void alternative(V& v, std::size_t index, std::index_sequence<I...>) {
    (void)((index == I ? (one(v.template emplace<I>()), true) : false) || ...);
  }

  std::string_view in_;
  std::size_t at_ = 0;
};

}  // namespace ncbridge::stepnc_codec::detail
