#include "feature_classification.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "milling_strategy.hpp"
#include "profile_fit.hpp"
#include "swept_area.hpp"

namespace ncbridge::feature_recognizer {
namespace {

Region stock_rectangle(const setup::Stock& stock) {
  return Region::rectangle({stock.min[0], stock.min[1], stock.max[0], stock.max[1]});
}

// The widest stock allowance around the part an outside profile may leave uncut (mm).
constexpr double kStockMargin = 5.0;

Point2 box_center(const Box2& b) { return {(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2}; }

// The largest area the group's cut surrounds without cutting it (the part, for an outside
// profile), if the group also covers everything between it and the stock's edge, or leaves
// only a margin along that edge (a stock allowance wider than the tool: one contour pass cuts
// the part out of it).
std::optional<Region> surrounded_part(const MillingGroup& group, const Region& stock_rect) {
  const double stock_area = stock_rect.area();
  // What the group's box leaves of the stock is certainly uncovered: a quick no for most groups.
  const auto box = group.filled.bbox();
  const auto stock_box = stock_rect.bbox();
  if (!box || !stock_box) return std::nullopt;
  const Box2 inner{stock_box->xmin + kStockMargin, stock_box->ymin + kStockMargin, stock_box->xmax - kStockMargin,
                   stock_box->ymax - kStockMargin};
  if (box->xmin > inner.xmin || box->ymin > inner.ymin || box->xmax < inner.xmax || box->ymax < inner.ymax) {
    return std::nullopt;
  }
  const Region uncovered = stock_rect.minus(group.filled);
  if (uncovered.area() > 0.005 * stock_area &&
      (inner.xmax <= inner.xmin || inner.ymax <= inner.ymin ||
       uncovered.intersected(Region::rectangle(inner)).area() > 0.005 * stock_area)) {
    return std::nullopt;
  }
  const Region inside = group.filled.minus(group.area);
  std::optional<Region> best;
  for (auto& c : inside.components()) {
    if (!best || c.area() > best->area()) best = c;
  }
  if (!best || best->area() < 0.1 * stock_area) return std::nullopt;
  return best->filled();
}

OperationType milling_operation_type(FeatureType type, bool finishing) {
  switch (type) {
    case FeatureType::PlanarFace:
      return finishing ? OperationType::PlaneFinishMilling : OperationType::PlaneRoughMilling;
    case FeatureType::GeneralOutsideProfile:
      return finishing ? OperationType::SideFinishMilling : OperationType::SideRoughMilling;
    case FeatureType::Region: return OperationType::FreeformOperation;
    default:
      return finishing ? OperationType::BottomAndSideFinishMilling : OperationType::BottomAndSideRoughMilling;
  }
}

double outer_perimeter(const Region& r) {
  double p = 0;
  for (const auto& pwh : r.polygons()) p += perimeter(pwh.outer);
  return p;
}

// The strategies already found for some layers (by index), so that none is analysed twice.
using KnownStrategies = std::vector<std::pair<std::size_t, StrategyAnalysis>>;

std::vector<RecognizedOperation> make_operations(const MillingGroup& group, const std::vector<Layer>& layers,
                                                 FeatureType type, const KnownStrategies& known = {}) {
  std::vector<RecognizedOperation> ops;
  const auto& last_op = group.operations.back();
  Region last_fill;
  double last_floor = 1e300;
  for (auto i : last_op.layers) {
    last_fill = last_fill.united(layers[i].area.filled());
    last_floor = std::min(last_floor, layers[i].z);
  }
  for (std::size_t k = 0; k < group.operations.size(); ++k) {
    const auto& lop = group.operations[k];
    const bool last = k + 1 == group.operations.size();
    // A single operation is a finish for faces and outside profiles (they reach their final
    // surface directly), a roughing for pockets, slots and steps.
    const bool finishing = last && (group.operations.size() > 1 || type == FeatureType::PlanarFace ||
                                    type == FeatureType::GeneralOutsideProfile);
    RecognizedOperation op;
    op.type = milling_operation_type(type, finishing);
    op.tool_number = lop.tool_number;
    op.layers = static_cast<int>(lop.layers.size());
    const Layer* deepest = &layers[lop.layers.front()];
    Region fill;
    double floor = 1e300;
    std::vector<double> levels;
    for (auto i : lop.layers) {
      const auto& l = layers[i];
      if (l.z < deepest->z) deepest = &l;
      fill = fill.united(l.area.filled());
      floor = std::min(floor, l.z);
      levels.push_back(l.z);
      for (auto w : l.workingsteps) op.workingsteps.push_back(w);
    }
    std::sort(op.workingsteps.begin(), op.workingsteps.end());
    op.workingsteps.erase(std::unique(op.workingsteps.begin(), op.workingsteps.end()), op.workingsteps.end());
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end(), [](double a, double b) { return std::abs(a - b) < 1e-3; }),
                 levels.end());
    for (std::size_t j = 1; j < levels.size(); ++j) op.axial_depth = std::max(op.axial_depth, levels[j] - levels[j - 1]);
    const std::size_t deepest_index = static_cast<std::size_t>(deepest - layers.data());
    const auto found = std::find_if(known.begin(), known.end(), [&](const auto& known_layer) { return known_layer.first == deepest_index; });
    const auto strategy = found != known.end() ? found->second : analyse_strategy(*deepest);
    op.strategy = strategy.strategy;
    op.radial_depth = strategy.stepover;
    op.feed = deepest->feed;
    op.spindle_rpm = deepest->spindle_rpm;
    if (!last) {
      const double per = outer_perimeter(last_fill);
      const double side = per > 0 ? (last_fill.area() - fill.area()) / per : 0;
      op.side_allowance = side > 0.01 ? side : 0;
      op.bottom_allowance = floor - last_floor > 0.01 ? floor - last_floor : 0;
    }
    ops.push_back(std::move(op));
  }
  return ops;
}

struct OpenContact {
  std::vector<OpenSide> sides;
  std::vector<Box2> pieces;
  double coverage[4] = {0, 0, 0, 0};  // length of each side of the part's box the cut opens
};

OpenContact open_contact(const Region& area, const PartEnvelope& part) {
  OpenContact out;
  const double near = kOpenBandWidth + 0.1;
  const Box2& e = part.box;
  for (const auto& piece : area.intersected(part.outside_band).components()) {
    if (piece.area() < 0.05 * kOpenBandWidth) continue;  // touches at a point
    const Box2 b = *piece.bbox();
    out.pieces.push_back(b);
    const double along_y = std::max(0.0, std::min(b.ymax, e.ymax) - std::max(b.ymin, e.ymin));
    const double along_x = std::max(0.0, std::min(b.xmax, e.xmax) - std::max(b.xmin, e.xmin));
    if (b.xmin <= e.xmin + near) out.coverage[0] += along_y;
    if (b.xmax >= e.xmax - near) out.coverage[1] += along_y;
    if (b.ymin <= e.ymin + near) out.coverage[2] += along_x;
    if (b.ymax >= e.ymax - near) out.coverage[3] += along_x;
  }
  const OpenSide names[4] = {OpenSide::XMinus, OpenSide::XPlus, OpenSide::YMinus, OpenSide::YPlus};
  for (int s = 0; s < 4; ++s) {
    if (out.coverage[s] > 0) out.sides.push_back(names[s]);
  }
  return out;
}

bool has_side(const OpenContact& c, OpenSide s) {
  return std::find(c.sides.begin(), c.sides.end(), s) != c.sides.end();
}

Ring outer_ring(const Region& r) {
  Ring best;
  double best_area = -1;
  for (const auto& pwh : r.polygons()) {
    const double a = Region::polygon(pwh.outer).area();
    if (a > best_area) best_area = a, best = pwh.outer;
  }
  return best;
}

// Groups by machining order, the latest first (their index order is not machining order:
// nested step-downs split off are appended).
void latest_first(std::vector<std::size_t>& indices, const std::vector<MillingGroup>& groups) {
  std::stable_sort(indices.begin(), indices.end(),
                   [&](std::size_t a, std::size_t b) { return groups[a].sequence > groups[b].sequence; });
}

// The ring (|outer| area minus |hole| area) by the shoelace formula, either orientation.
double ring_area(const Ring& ring) {
  double twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& a = ring[i];
    const auto& b = ring[(i + 1) % ring.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return std::abs(twice) / 2;
}

// A boss left standing: the largest area the group's cut surrounds without cutting it, when no
// other group cuts into it either (so material stands there), and the cut does not go through
// (a core inside a through cut falls out). Its outside profile is what the group machined.
// The cut must hug the island (a ring about one tool wide, as a profile pass leaves): a pocket
// or step cleared around an island is wider.
// `groove`, when given, is set when the cut hugs such an island but the material around it stands
// too: a groove along a contour (an engraved outline, a profile cut into a blank thicker than it).
std::optional<Region> standing_island(std::size_t group_index, const std::vector<MillingGroup>& groups,
                                      const std::vector<Layer>& layers, const PartEnvelope& part, double tool_diameter,
                                      bool* groove = nullptr) {
  const auto& group = groups[group_index];
  if (group.floor <= part.bottom_z + 1e-3) return std::nullopt;
  const Ring* island_ring = nullptr;
  double island_area = 0, ring_width = 0;
  const auto polygons = group.area.polygons();
  for (const auto& pwh : polygons) {
    for (const auto& hole : pwh.holes) {
      const double a = ring_area(hole);
      if (a <= island_area) continue;
      const double ring_area_around = ring_area(pwh.outer) - a;
      ring_width = ring_area_around / ((perimeter(pwh.outer) + perimeter(hole)) / 2);
      island_area = a, island_ring = &hole;
    }
  }
  if (!island_ring || island_area < 1.0 || ring_width > 1.5 * tool_diameter) return std::nullopt;
  const Region island = Region::polygon(*island_ring);
  // Cuts above the group's highest level (a face over the boss) leave it standing; a cut into the
  // island (of the latest kNearFeatureLimit near it) means no boss stands there.
  double highest = group.floor;
  for (auto i : group.layers()) highest = std::max(highest, layers[i].z);
  const auto box = island.bbox();
  std::vector<std::size_t> into;
  for (auto g : part.groups_by_box.latest(*box, kNearCandidateLimit)) {
    if (g == group_index || groups[g].floor > highest + 1e-3 || !boxes_overlap(box, groups[g].area.bbox())) continue;
    into.push_back(g);
  }
  latest_first(into, groups);
  into.resize(std::min(into.size(), near_feature_limit(into.size())));
  // (A groove's island may hold shallower grooves of its own: engraved outlines one in another.)
  bool boss = true;
  Region cut_into;
  for (auto g : into) {
    const Region cut = island.intersected(groups[g].area);
    if (cut.area() > 0.05 * island.area()) {
      if (!groove) return std::nullopt;
      boss = false;
    }
    cut_into = cut_into.united(cut);
  }
  if (!boss && cut_into.area() > 0.5 * island.area()) return std::nullopt;
  // Around a boss the material is cleared too (or it is the part's edge); a ring cut into solid
  // material is a hole bored by circular interpolation, its core a chip.
  Region ring_fill;
  for (const auto& pwh : polygons) {
    const Region outer = Region::polygon(pwh.outer);
    if (outer.intersected(island).area() > 0) ring_fill = outer;
  }
  const Region outside = boundary_band(ring_fill, 0.25 * tool_diameter, 0.01).minus(ring_fill);
  Region cleared = outside.minus(part.outline);
  std::vector<std::size_t> around;
  if (const auto outside_box = outside.bbox()) {
    for (auto g : part.groups_by_box.latest(*outside_box, kNearCandidateLimit)) {
      if (g != group_index && boxes_overlap(outside_box, groups[g].area.bbox())) around.push_back(g);
    }
  }
  latest_first(around, groups);
  around.resize(std::min(around.size(), near_feature_limit(around.size())));
  std::sort(around.begin(), around.end());
  for (auto g : around) cleared = cleared.united(outside.intersected(groups[g].area));
  if (cleared.area() < 0.5 * outside.area()) {
    if (groove) *groove = true;
    return std::nullopt;
  }
  if (!boss) return std::nullopt;
  return island;
}

// What earlier features near a group cut to its floor or deeper (air at its level): the latest
// kNearFeatureLimit of them (bounded exact work). Kept as the features' areas, not their union:
// the questions asked of it meet each area with something small (a band along an edge, a strip
// along a side, a footprint), where uniting the areas first would resolve every crossing among
// them.
class RemovedBefore {
 public:
  RemovedBefore() = default;  // nothing
  RemovedBefore(const MillingGroup& group, const std::vector<MillingGroup>& groups, const PartEnvelope& part) {
    auto near = group.area.bbox();
    if (!near) return;
    near->xmin -= 1, near->ymin -= 1, near->xmax += 1, near->ymax += 1;
    std::vector<std::size_t> earlier;
    for (auto index : part.groups_by_box.latest(*near, kNearCandidateLimit)) {
      const auto& g = groups[index];
      if (g.sequence < group.sequence && g.floor <= group.floor + 1e-3 && boxes_overlap(near, g.area.bbox())) {
        earlier.push_back(index);
      }
    }
    latest_first(earlier, groups);
    earlier.resize(std::min(earlier.size(), near_feature_limit(earlier.size())));
    std::sort(earlier.begin(), earlier.end());
    for (auto index : earlier) areas_.push_back(groups[index].area);
  }

  bool empty() const { return areas_.empty(); }

  // `region` less what was removed.
  Region left_of(Region region) const {
    for (const auto& a : areas_) region = region.minus(a);
    return region;
  }

  // The part of `region` that was removed.
  Region within(const Region& region) const {
    std::vector<Region> parts;
    for (const auto& a : areas_) parts.push_back(region.intersected(a));
    return Region::union_all(parts);
  }

 private:
  std::vector<Region> areas_;
};

// The length of a side of the part (0 to 3: x-, x+, y-, y+) where material still stands at the
// group's floor: earlier groups cutting to that floor or deeper have removed the rest. A step
// runs along most of what stands there.
double standing_side_length(int side, const RemovedBefore& removed, const PartEnvelope& part) {
  constexpr double kStrip = 1.0;
  const Box2& e = part.box;
  const Box2 strips[4] = {{e.xmin, e.ymin, e.xmin + kStrip, e.ymax}, {e.xmax - kStrip, e.ymin, e.xmax, e.ymax},
                          {e.xmin, e.ymin, e.xmax, e.ymin + kStrip}, {e.xmin, e.ymax - kStrip, e.xmax, e.ymax}};
  return removed.left_of(Region::rectangle(strips[side]).intersected(part.outline)).area() / kStrip;
}

// The straight centre line of a slot whose area is the rectangle `rect`.
std::vector<Point2> rectangle_course(const OrientedRectangle& rect, double end_inset) {
  const double a = rect.angle_deg * 3.14159265358979323846 / 180;
  const double half = rect.length / 2 - end_inset;
  return {{rect.center.x - half * std::cos(a), rect.center.y - half * std::sin(a)},
          {rect.center.x + half * std::cos(a), rect.center.y + half * std::sin(a)}};
}

// A group of coarse layers (beyond the work limit): a `region` of the box its paths sweep,
// from its floor, with one operation per layer.
ClassifiedFeature coarse_feature(const MillingGroup& group, const std::vector<Layer>& layers) {
  ClassifiedFeature out;
  out.order = group.sequence;
  auto& f = out.feature;
  f.type = FeatureType::Region;
  f.approximate = true;
  f.bottom = BottomCondition::General;
  f.bottom_z = group.floor;
  Box2 box{1e300, 1e300, -1e300, -1e300};
  for (auto i : group.layers()) {
    const auto& e = layers[i].extent;
    box = {std::min(box.xmin, e.xmin), std::min(box.ymin, e.ymin), std::max(box.xmax, e.xmax), std::max(box.ymax, e.ymax)};
  }
  f.x = (box.xmin + box.xmax) / 2, f.y = (box.ymin + box.ymax) / 2;
  f.profile.shape = ProfileShape::GeneralClosed;
  f.profile.outline = {{box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}};
  f.profile.length = std::max(box.width(), box.height());
  f.profile.width = std::min(box.width(), box.height());
  f.profile.angle_deg = box.width() >= box.height() ? 0 : 90;
  f.operations = make_operations(group, layers, f.type);
  return out;
}

}  // namespace

PartEnvelope find_part_envelope(const std::vector<MillingGroup>& groups, const setup::Stock& stock,
                                double tolerance) {
  PartEnvelope part;
  const Region stock_rect = stock_rectangle(stock);
  part.stock = stock_rect;
  part.outline = stock_rect;
  part.bottom_z = stock.min[2];
  std::optional<double> profile_floor;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (auto box = groups[g].area.bbox()) part.groups_by_box.insert(g, *box);
    if (groups[g].freeform || groups[g].coarse) continue;
    if (auto inside = surrounded_part(groups[g], stock_rect)) {
      part.outline = part.outline.intersected(*inside);
      part.outside_profiles.push_back(g);
      profile_floor = std::min(profile_floor.value_or(groups[g].floor), groups[g].floor);
    }
  }
  if (profile_floor) part.bottom_z = std::max(part.bottom_z, *profile_floor);
  part.box = part.outline.bbox().value_or(Box2{stock.min[0], stock.min[1], stock.max[0], stock.max[1]});
  // From just inside the outline: a cut whose edge runs along the part's edge (a pocket not
  // extended beyond an open side) is open there too.
  const Region edge = boundary_band(part.outline, kOpenEdgeInset, tolerance);
  part.outside_band = boundary_band(part.outline, kOpenBandWidth, tolerance).minus(part.outline).united(edge.intersected(part.outline));
  return part;
}

std::optional<ClassifiedFeature> classify_group(std::size_t group_index, const std::vector<MillingGroup>& groups,
                                                const std::vector<Layer>& layers, const PartEnvelope& part,
                                                WorkBudget& budget) {
  const auto& group = groups[group_index];
  ClassifiedFeature out;
  out.order = group.sequence;
  auto& f = out.feature;
  f.bottom_z = group.floor;
  if (group.coarse) return coarse_feature(group, layers);
  const WorkCharge charge(budget);
  const bool is_profile = std::find(part.outside_profiles.begin(), part.outside_profiles.end(), group_index) !=
                          part.outside_profiles.end();
  const auto& first_tool = layers[group.operations.front().layers.front()].tool;

  if (is_profile) {
    f.type = FeatureType::GeneralOutsideProfile;
    out.footprint = group.area.intersected(part.stock);
    const Region inside = group.filled.minus(group.area);
    Region biggest;
    for (auto& c : inside.components()) {
      if (c.area() > biggest.area()) biggest = c;
    }
    const Ring outline = outer_ring(biggest);
    f.profile = fit_closed_profile(outline, biggest.filled().area());
    if (f.profile.shape == ProfileShape::Rectangular || f.profile.shape == ProfileShape::Circular) {
      const auto rect = minimum_area_rectangle(outline);
      f.x = rect.center.x, f.y = rect.center.y;
    } else {
      const Point2 c = box_center(*biggest.bbox());
      f.x = c.x, f.y = c.y;
    }
    f.bottom = group.floor <= part.bottom_z + 1e-3 ? BottomCondition::Through : BottomCondition::Planar;
    if (f.bottom == BottomCondition::Through) f.bottom_z = part.bottom_z;
    f.operations = make_operations(group, layers, f.type);
    return out;
  }

  const Region footprint = group.area.intersected(part.outline);
  if (footprint.area() < 1e-6) return std::nullopt;
  out.footprint = footprint;
  const Box2 fbox = *footprint.bbox();
  const Point2 fcenter = box_center(fbox);
  f.bottom = group.floor <= part.bottom_z + 1e-3 ? BottomCondition::Through : BottomCondition::Planar;
  if (f.bottom == BottomCondition::Through) f.bottom_z = part.bottom_z;  // CAM cuts a little below

  KnownStrategies known;
  auto finish = [&](FeatureType type) {
    f.type = type;
    f.operations = make_operations(group, layers, type, known);
    return out;
  };

  if (group.freeform) {
    f.x = fcenter.x, f.y = fcenter.y;
    f.bottom = BottomCondition::General;
    f.profile.outline = outer_ring(footprint);
    f.profile.shape = ProfileShape::GeneralClosed;
    return finish(FeatureType::Region);
  }

  const double part_area = part.outline.area();
  if (first_tool.type == setup::ToolType::FaceMill || footprint.filled().area() >= 0.95 * part_area) {
    f.x = fcenter.x, f.y = fcenter.y;
    f.profile.shape = ProfileShape::Linear;
    f.profile.length = std::max(fbox.width(), fbox.height());
    f.profile.width = std::min(fbox.width(), fbox.height());
    f.profile.angle_deg = fbox.width() >= fbox.height() ? 0 : 90;
    f.bottom = BottomCondition::None;
    return finish(FeatureType::PlanarFace);
  }

  std::vector<StrategyAnalysis> strategies;
  for (auto i : group.layers()) {
    strategies.push_back(analyse_strategy(layers[i]));
    known.emplace_back(i, strategies.back());
  }
  // A hole milled by interpolation: in every layer circles about one centre, one radius or a
  // helix at each of several radii (a circular pocket is cleared by flat concentric circles).
  const bool all_circles = std::all_of(strategies.begin(), strategies.end(), [&](const auto& s) {
    return !s.circle_radii.empty() && (s.single_circle || s.helical) &&
           std::hypot(s.circle_center.x - strategies.front().circle_center.x,
                      s.circle_center.y - strategies.front().circle_center.y) < 0.05;
  });
  const bool all_helical = std::all_of(strategies.begin(), strategies.end(), [](const auto& s) { return s.helical; });

  // A helix leaving a core is a hole (CAM does not leave pins standing in a blind hole).
  const bool compare = budget.available();  // with other features, within the work limit
  if (!compare) f.approximate = true;
  bool groove = false;
  auto island = (all_circles && all_helical) || !compare
                    ? std::nullopt
                    : standing_island(group_index, groups, layers, part, first_tool.diameter, &groove);
  // A groove along a contour with material standing on both sides, not through and not a ring
  // about one centre (a bore, its core a chip): no feature of ISO 14649-10 that CC2 writes here
  // (a pocket with an island needs its_boss); its workingsteps stay as the toolpaths they are,
  // rather than a pocket that would clear the island.
  if (groove && !all_circles && f.bottom != BottomCondition::Through) return std::nullopt;
  if (island) {
    f.type = FeatureType::GeneralOutsideProfile;
    const Ring boss = outer_ring(*island);
    f.profile = fit_closed_profile(boss, island->area());
    const auto rect = minimum_area_rectangle(boss);
    f.x = rect.center.x, f.y = rect.center.y;
    f.bottom = BottomCondition::Planar;
    out.footprint = *island;  // its top is the boss's
    f.operations = make_operations(group, layers, f.type, known);
    return out;
  }

  auto contact = open_contact(group.area, part);
  // Open also where the cut's outer edge runs into what earlier features cleared deeper (an open
  // pocket on an upper level opening onto a step): a band just inside the edge, in that air.
  const RemovedBefore removed = compare ? RemovedBefore(group, groups, part) : RemovedBefore();
  if (!removed.empty()) {
    std::vector<Region> outers;
    for (const auto& pwh : group.area.polygons()) outers.push_back(Region::polygon(pwh.outer));
    const Region outer = Region::union_all(outers);
    const Region edge = boundary_band(outer, kOpenBandWidth, 0.01).intersected(outer);
    for (const auto& piece : removed.within(edge).components()) {
      if (piece.area() >= 0.05 * kOpenBandWidth) contact.pieces.push_back(*piece.bbox());
    }
  }
  const bool all_center_lines = std::all_of(strategies.begin(), strategies.end(), [](const auto& s) {
    return s.strategy == Strategy::CenterMilling;
  });
  const double tool_d = first_tool.diameter;
  const Ring outline = outer_ring(footprint);
  const auto rect = minimum_area_rectangle(outline);

  if (contact.pieces.empty()) {
    if (all_circles) {
      const auto& s = strategies.front();
      double radius = 0;
      for (const auto& l : strategies) radius = std::max(radius, l.circle_radius);
      f.x = s.circle_center.x, f.y = s.circle_center.y;
      f.diameter = 2 * radius + tool_d;
      f.profile.shape = ProfileShape::Circular;
      f.profile.diameter = f.diameter;
      if (f.bottom != BottomCondition::Through) f.bottom = BottomCondition::Planar;
      return finish(FeatureType::RoundHole);
    }
    f.profile = fit_closed_profile(outline, footprint.filled().area());
    const bool stadium = f.profile.shape == ProfileShape::Rectangular &&
                         f.profile.corner_radius >= 0.45 * f.profile.width && f.profile.length >= 1.2 * f.profile.width;
    if (all_center_lines || stadium) {
      f.x = rect.center.x, f.y = rect.center.y;
      f.slot_width = all_center_lines ? tool_d : rect.width;
      f.slot_ends = {SlotEnd::Radiused, SlotEnd::Radiused};
      f.slot_course = rectangle_course(rect, f.slot_width / 2);
      return finish(FeatureType::Slot);
    }
    f.x = rect.center.x, f.y = rect.center.y;
    return finish(FeatureType::ClosedPocket);
  }

  f.open_sides = contact.sides;
  const Region standing_footprint = removed.left_of(footprint);
  const Point2 open_center = standing_footprint.area() > 0.05 * footprint.area() ? box_center(*standing_footprint.bbox()) : fcenter;
  f.x = open_center.x, f.y = open_center.y;
  f.profile.outline = outline;
  f.profile.length = rect.length;
  f.profile.width = rect.width;
  f.profile.angle_deg = rect.angle_deg;
  f.profile.shape = ProfileShape::GeneralClosed;

  for (int s = 0; s < 4; ++s) {
    if (contact.coverage[s] <= 0.9) continue;  // cannot be 90 % of more than 1 mm standing
    const double standing = standing_side_length(s, removed, part);
    if (standing > 1.0 && contact.coverage[s] >= 0.9 * standing) {
      f.bottom = BottomCondition::None;
      return finish(FeatureType::Step);
    }
  }
  const bool across_x = has_side(contact, OpenSide::XMinus) && has_side(contact, OpenSide::XPlus);
  const bool across_y = has_side(contact, OpenSide::YMinus) && has_side(contact, OpenSide::YPlus);
  const bool strip = rect.length > 0 && footprint.area() >= 0.95 * rect.length * rect.width;
  if (contact.pieces.size() >= 2 && (across_x || across_y) && strip) {
    f.x = rect.center.x, f.y = rect.center.y;
    f.slot_width = rect.width;
    f.slot_ends = {SlotEnd::Open, SlotEnd::Open};
    f.slot_course = rectangle_course(rect, 0);
    f.profile.shape = ProfileShape::Linear;
    return finish(FeatureType::Slot);
  }
  return finish(FeatureType::OpenPocket);
}

}  // namespace ncbridge::feature_recognizer
