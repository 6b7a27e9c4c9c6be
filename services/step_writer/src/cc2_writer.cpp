// CC2 features -> Part 21, attribute orders of combined_schema_iso14649_only.exp:
// MANUFACTURING_FEATURE (its_id, its_workpiece, its_operations), TWO5D_MANUFACTURING_FEATURE
// (feature_placement), MACHINING_FEATURE (depth), then the subtype's own attributes.
#include "cc2_writer.hpp"

#include <stdexcept>
#include <type_traits>

namespace ncbridge::step_writer::cc2 {

namespace {

using part21::InstanceId;
using part21::InstanceStream;
namespace sn = stepnc;

template <class... F> struct Overload : F... { using F::operator()...; };
template <class... F> Overload(F...) -> Overload<F...>;

class FeatureWriter {
 public:
  FeatureWriter(InstanceStream& s, SharedGeometry& g, InstanceId workpiece, const std::vector<InstanceId>& ops)
      : s_(s), g_(g), workpiece_(workpiece), ops_(ops) {}

  InstanceId write(const sn::Feature& f) {
    return std::visit(Overload{
        [&](const sn::PlanarFace& p) {
          const Common c = common(p);
          const InstanceId course = linear_path(p.course_of_travel);
          const InstanceId removal = linear_profile(p.removal_boundary);
          const InstanceId boundary = p.face_boundary ? closed_profile(*p.face_boundary) : 0;
          begin("PLANAR_FACE", c);
          s_.ref(course);
          s_.ref(removal);
          s_.opt_ref(boundary);
          s_.open_list();  // its_boss
          s_.close_list();
          return s_.end();
        },
        [&](const sn::ClosedPocket& p) {
          const Common c = common(p);
          const Pocket k = pocket(p);
          const InstanceId boundary = closed_profile(p.feature_boundary);
          begin("CLOSED_POCKET", c);
          pocket_attributes(p, k);
          s_.ref(boundary);
          return s_.end();
        },
        [&](const sn::OpenPocket& p) {
          const Common c = common(p);
          const Pocket k = pocket(p);
          const InstanceId open = open_profile(p.open_boundary);
          const InstanceId wall = p.wall_boundary ? open_profile(*p.wall_boundary) : 0;
          begin("OPEN_POCKET", c);
          pocket_attributes(p, k);
          s_.ref(open);
          s_.opt_ref(wall);
          return s_.end();
        },
        [&](const sn::Slot& p) {
          const Common c = common(p);
          const InstanceId course = linear_path(p.course_of_travel);
          const InstanceId shape = open_profile(p.swept_shape);
          std::vector<InstanceId> ends;
          for (auto e : p.end_conditions) ends.push_back(slot_end(e));
          begin("SLOT", c);
          s_.ref(course);
          s_.ref(shape);
          s_.refs(ends);
          return s_.end();
        },
        [&](const sn::Step& p) {
          const Common c = common(p);
          const InstanceId open = linear_path(p.open_boundary);
          begin("STEP", c);
          s_.ref(open);
          s_.unset();      // wall_boundary
          s_.open_list();  // its_boss
          s_.close_list();
          return s_.end();
        },
        [&](const sn::GeneralOutsideProfile& p) {
          const Common c = common(p);
          const InstanceId swept = linear_path(p.profile_swept_shape);
          const InstanceId shape = g_.curve(p.feature_boundary);
          s_.begin(p.closed ? "GENERAL_CLOSED_PROFILE" : "GENERAL_PROFILE");
          s_.unset();
          s_.ref(shape);
          const InstanceId boundary = s_.end();
          begin("GENERAL_OUTSIDE_PROFILE", c);
          s_.ref(swept);
          s_.ref(boundary);
          return s_.end();
        },
        [&](const sn::Region& r) {
          // REGION is abstract: its subtype REGION_PROJECTION (the outline projected to a depth).
          const InstanceId placement = r.feature_placement ? g_.placement(*r.feature_placement, "FEATURE PLACEMENT") : 0;
          const InstanceId curve = g_.curve(r.proj_curve);
          const InstanceId dir = g_.direction(r.proj_dir);
          const InstanceId depth = g_.toleranced(r.depth);
          s_.begin("REGION_PROJECTION");
          s_.string(r.its_id);
          s_.ref(workpiece_);
          s_.refs(ops_);
          s_.opt_ref(placement);
          s_.ref(curve);
          s_.ref(dir);
          s_.ref(depth);
          return s_.end();
        },
        [&](const auto&) -> InstanceId { throw std::logic_error("cc2::write_feature: not a CC2 feature"); }},
        f);
  }

 private:
  struct Common {
    std::string_view id;
    InstanceId placement, depth;
  };
  Common common(const sn::MachiningFeature& m) {
    const InstanceId placement = g_.placement(m.feature_placement, "FEATURE PLACEMENT");
    const InstanceId depth = g_.plane(m.depth, "DEPTH PLANE");
    return {m.its_id, placement, depth};
  }
  void begin(std::string_view entity, const Common& c) {
    s_.begin(entity);
    s_.string(c.id);
    s_.ref(workpiece_);
    s_.refs(ops_);
    s_.ref(c.placement);
    s_.ref(c.depth);
  }

  InstanceId opt_placement(const std::optional<sn::Axis2Placement3d>& a) {
    return a ? g_.placement(*a, "PROFILE PLACEMENT") : 0;
  }
  InstanceId linear_path(const sn::LinearPath& p) {
    const InstanceId placement = opt_placement(p.placement);
    const InstanceId distance = g_.toleranced(p.distance);
    const InstanceId dir = g_.direction(p.its_direction);
    s_.begin("LINEAR_PATH");
    s_.opt_ref(placement);
    s_.ref(distance);
    s_.ref(dir);
    return s_.end();
  }
  InstanceId linear_profile(const sn::LinearProfile& p) {
    const InstanceId placement = opt_placement(p.placement);
    s_.begin("NUMERIC_PARAMETER");
    s_.string("PROFILE LENGTH");
    s_.real(p.profile_length);
    s_.string("MM");
    const InstanceId length = s_.end();
    s_.begin("LINEAR_PROFILE");
    s_.opt_ref(placement);
    s_.ref(length);
    return s_.end();
  }
  InstanceId closed_profile(const sn::ClosedProfile& c) {
    return std::visit(Overload{
        [&](const sn::RectangularClosedProfile& r) {
          const InstanceId placement = opt_placement(r.placement);
          const InstanceId width = g_.toleranced(r.profile_width);
          const InstanceId length = g_.toleranced(r.profile_length);
          s_.begin("RECTANGULAR_CLOSED_PROFILE");
          s_.opt_ref(placement);
          s_.ref(width);
          s_.ref(length);
          return s_.end();
        },
        [&](const sn::CircularClosedProfile& r) {
          const InstanceId placement = opt_placement(r.placement);
          const InstanceId diameter = g_.toleranced(r.diameter);
          s_.begin("CIRCULAR_CLOSED_PROFILE");
          s_.opt_ref(placement);
          s_.ref(diameter);
          return s_.end();
        },
        [&](const sn::GeneralClosedProfile& r) {
          const InstanceId placement = opt_placement(r.placement);
          const InstanceId shape = g_.curve(r.closed_profile_shape);
          s_.begin("GENERAL_CLOSED_PROFILE");
          s_.opt_ref(placement);
          s_.ref(shape);
          return s_.end();
        }},
        c);
  }
  InstanceId open_profile(const sn::OpenProfile& o) {
    return std::visit(Overload{[&](const sn::LinearProfile& l) { return linear_profile(l); },
                               [&](const sn::GeneralProfile& p) {
                                 const InstanceId placement = opt_placement(p.placement);
                                 const InstanceId shape = g_.curve(p.its_profile);
                                 s_.begin("GENERAL_PROFILE");
                                 s_.opt_ref(placement);
                                 s_.ref(shape);
                                 return s_.end();
                               }},
                      o);
  }

  struct Pocket {
    InstanceId bottom, planar_radius, orthogonal_radius;
  };
  template <class P>
  Pocket pocket(const P& p) {
    s_.begin(std::holds_alternative<sn::ThroughPocketBottomCondition>(p.bottom_condition) ? "THROUGH_POCKET_BOTTOM_CONDITION"
                                                                                          : "PLANAR_POCKET_BOTTOM_CONDITION");
    const InstanceId bottom = s_.end();
    const InstanceId planar = p.planar_radius ? g_.toleranced(*p.planar_radius) : 0;
    const InstanceId orthogonal = p.orthogonal_radius ? g_.toleranced(*p.orthogonal_radius) : 0;
    return {bottom, planar, orthogonal};
  }
  // POCKET's attributes: its_boss, slope, bottom_condition, planar_radius, orthogonal_radius.
  template <class P>
  void pocket_attributes(const P& p, const Pocket& k) {
    s_.open_list();
    s_.close_list();
    s_.opt_real(p.slope);
    s_.ref(k.bottom);
    s_.opt_ref(k.planar_radius);
    s_.opt_ref(k.orthogonal_radius);
  }

  InstanceId slot_end(sn::SlotEndType e) {
    // Flat ends' corner radii and woodruff radii are not modelled: the smallest the schema allows.
    const sn::TolerancedLengthMeasure smallest{0.001, 0.001, 0.001, 3};
    switch (e) {
      case sn::SlotEndType::Open: s_.begin("OPEN_SLOT_END_TYPE"); return s_.end();
      case sn::SlotEndType::Radiused: s_.begin("RADIUSED_SLOT_END_TYPE"); return s_.end();
      case sn::SlotEndType::Loop: s_.begin("LOOP_SLOT_END_TYPE"); return s_.end();
      case sn::SlotEndType::Flat: {
        const InstanceId r1 = g_.toleranced(smallest), r2 = g_.toleranced(smallest);
        s_.begin("FLAT_SLOT_END_TYPE");
        s_.ref(r1);
        s_.ref(r2);
        return s_.end();
      }
      case sn::SlotEndType::Woodruff: break;
    }
    const InstanceId r = g_.toleranced(smallest);
    s_.begin("WOODRUFF_SLOT_END_TYPE");
    s_.ref(r);
    return s_.end();
  }

  InstanceStream& s_;
  SharedGeometry& g_;
  InstanceId workpiece_;
  const std::vector<InstanceId>& ops_;
};

}  // namespace

bool is_cc2_feature(const stepnc::Feature& feature) {
  return !std::holds_alternative<stepnc::ToolpathFeature>(feature) && !std::holds_alternative<stepnc::RoundHole>(feature);
}

part21::InstanceId write_feature(part21::InstanceStream& s, SharedGeometry& g, const stepnc::Feature& feature,
                                 part21::InstanceId workpiece, const std::vector<part21::InstanceId>& operations) {
  return FeatureWriter(s, g, workpiece, operations).write(feature);
}

}  // namespace ncbridge::step_writer::cc2
