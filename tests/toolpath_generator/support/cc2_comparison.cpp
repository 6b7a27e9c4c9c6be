#include "cc2_comparison.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <type_traits>

#include "ncbridge/material_check/feature_region.hpp"

namespace ncbridge::test_support {

namespace {

namespace sn = stepnc;

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4f", v);
  return b;
}

const sn::Axis2Placement3d* placement(const sn::Feature& f) {
  return std::visit(
      [](const auto& x) -> const sn::Axis2Placement3d* {
        using F = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<F, sn::Region>) return x.feature_placement ? &*x.feature_placement : nullptr;
        else return &x.feature_placement;
      },
      f);
}

double depth(const sn::Feature& f) {
  return std::visit(
      [](const auto& x) -> double {
        using F = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<F, sn::Region>) return x.depth.theoretical_size;
        else return -x.depth.position.location.z;
      },
      f);
}

// The dimensions a feature states, named.
std::vector<std::pair<std::string, double>> dimensions(const sn::Feature& f) {
  std::vector<std::pair<std::string, double>> d;
  auto closed = [&](const sn::ClosedProfile& p) {
    if (const auto* r = std::get_if<sn::RectangularClosedProfile>(&p)) {
      d.emplace_back("width", r->profile_width.theoretical_size);
      d.emplace_back("length", r->profile_length.theoretical_size);
    } else if (const auto* c = std::get_if<sn::CircularClosedProfile>(&p)) {
      d.emplace_back("diameter", c->diameter.theoretical_size);
    }
  };
  std::visit(
      [&](const auto& x) {
        using F = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<F, sn::RoundHole>) {
          d.emplace_back("diameter", x.diameter.theoretical_size);
        } else if constexpr (std::is_same_v<F, sn::PlanarFace>) {
          d.emplace_back("course", x.course_of_travel.distance.theoretical_size);
          d.emplace_back("removal width", x.removal_boundary.profile_length);
        } else if constexpr (std::is_same_v<F, sn::ClosedPocket>) {
          closed(x.feature_boundary);
          d.emplace_back("corner radius", x.orthogonal_radius ? x.orthogonal_radius->theoretical_size : 0);
        } else if constexpr (std::is_same_v<F, sn::Slot>) {
          d.emplace_back("course", x.course_of_travel.distance.theoretical_size);
          if (const auto* w = std::get_if<sn::LinearProfile>(&x.swept_shape)) d.emplace_back("width", w->profile_length);
        } else if constexpr (std::is_same_v<F, sn::Step>) {
          d.emplace_back("length", x.open_boundary.distance.theoretical_size);
        }
      },
      f);
  return d;
}

std::string bottom(const sn::Feature& f) {
  if (const auto* h = std::get_if<sn::RoundHole>(&f)) {
    if (std::holds_alternative<sn::ThroughBottomCondition>(h->bottom_condition)) return "through";
    if (std::holds_alternative<sn::ConicalHoleBottom>(h->bottom_condition)) return "conical";
    return "flat";
  }
  if (const auto* p = std::get_if<sn::ClosedPocket>(&f)) return std::holds_alternative<sn::ThroughPocketBottomCondition>(p->bottom_condition) ? "through" : "planar";
  if (const auto* p = std::get_if<sn::OpenPocket>(&f)) return std::holds_alternative<sn::ThroughPocketBottomCondition>(p->bottom_condition) ? "through" : "planar";
  return "";
}

std::string direction(const std::optional<sn::Direction>& d) {
  return d ? "(" + num(d->x) + "," + num(d->y) + ")" : "$";
}

// The strategy as compared: its entity and what it states.
std::string strategy(const sn::Operation& op) {
  const auto* m = std::visit(
      [](const auto& o) -> const sn::Two5DMillingOperation* {
        if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, std::decay_t<decltype(o)>>) return &o;
        else return nullptr;
      },
      op);
  if (!m) return "";
  if (!m->its_machining_strategy) return "$";
  return std::visit(
      [](const auto& s) -> std::string {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, sn::Unidirectional>) return "UNIDIRECTIONAL " + direction(s.feed_direction);
        else if constexpr (std::is_same_v<S, sn::Bidirectional>) {
          return "BIDIRECTIONAL " + direction(s.feed_direction) + " " +
                 (s.stepover_direction ? (*s.stepover_direction == sn::LeftOrRight::Left ? "LEFT" : "RIGHT") : "$");
        } else if constexpr (std::is_same_v<S, sn::ContourParallel> || std::is_same_v<S, sn::ContourSpiral>) {
          std::string r = std::is_same_v<S, sn::ContourParallel> ? "CONTOUR_PARALLEL" : "CONTOUR_SPIRAL";
          r += s.rotation_direction ? (*s.rotation_direction == sn::RotDirection::Cw ? " CW" : " CCW") : " $";
          r += s.cutmode ? (*s.cutmode == sn::CutmodeType::Climb ? " CLIMB" : " CONVENTIONAL") : " $";
          return r;
        } else if constexpr (std::is_same_v<S, sn::BidirectionalContour> || std::is_same_v<S, sn::ContourBidirectional>) {
          std::string r = std::is_same_v<S, sn::BidirectionalContour> ? "BIDIRECTIONAL_CONTOUR " : "CONTOUR_BIDIRECTIONAL ";
          r += direction(s.feed_direction) + " " + (s.stepover_direction ? (*s.stepover_direction == sn::LeftOrRight::Left ? "LEFT" : "RIGHT") : "$");
          r += s.rotation_direction ? (*s.rotation_direction == sn::RotDirection::Cw ? " CW" : " CCW") : " $";
          r += s.spiral_cutmode ? (*s.spiral_cutmode == sn::CutmodeType::Climb ? " CLIMB" : " CONVENTIONAL") : " $";
          return r;
        } else {
          static_assert(std::is_same_v<S, sn::CenterMilling>);
          return "CENTER_MILLING";
        }
      },
      *m->its_machining_strategy);
}

struct OperationSummary {
  std::string entity, tool, strategy;
};

std::vector<OperationSummary> operations_of(const sn::Project& p, std::size_t feature) {
  std::vector<OperationSummary> out;
  for (const auto& e : p.main_workplan.its_elements) {
    const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e);
    if (!ws || ws->its_feature.index != feature) continue;
    const auto& op = p.operation(ws->its_operation);
    out.push_back({std::string(sn::entity_name(op)), p.tool(sn::machining_operation(op).its_tool).its_id, strategy(op)});
  }
  return out;
}

bool same_directions_impl(const std::string& a, const std::string& b, double tol) {
  // Compare the numbers of two strategy texts within tol, the words exactly.
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const bool na = std::isdigit(static_cast<unsigned char>(a[i])) || a[i] == '-', nb = std::isdigit(static_cast<unsigned char>(b[j])) || b[j] == '-';
    if (na && nb) {
      std::size_t ea, eb;
      const double x = std::stod(a.substr(i), &ea), y = std::stod(b.substr(j), &eb);
      if (std::abs(x - y) > tol) return false;
      i += ea, j += eb;
      continue;
    }
    if (a[i] != b[j]) return false;
    ++i, ++j;
  }
  return i == a.size() && j == b.size();
}

// The middle of the box of what the feature removes.
material_check::Point2 centre_of(const sn::Feature& f, std::size_t index, const setup::Stock& stock) {
  const auto r = material_check::feature_region(f, index, stock);
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  const auto& outer = std::holds_alternative<sn::GeneralOutsideProfile>(f) ? r.outline.back() : r.outline.front();
  for (const auto& p : outer.points(1e-4)) {
    xmin = std::min(xmin, p.x), ymin = std::min(ymin, p.y), xmax = std::max(xmax, p.x), ymax = std::max(ymax, p.y);
  }
  return {(xmin + xmax) / 2, (ymin + ymax) / 2};
}

}  // namespace

Cc2Comparison compare_cc2(const sn::Project& expected, const sn::Project& actual, const setup::Stock& stock,
                          const ComparisonTolerances& t) {
  Cc2Comparison out;
  std::vector<bool> used(actual.features.size(), false);
  for (std::size_t i = 0; i < expected.features.size(); ++i) {
    const auto& f = expected.features[i];
    if (std::holds_alternative<sn::ToolpathFeature>(f)) continue;
    bool machined = false;
    for (const auto& e : expected.main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) machined = machined || ws->its_feature.index == i;
    }
    if (!machined) continue;
    ++out.features;
    const std::string id = sn::feature_id(f);
    const auto* pa = placement(f);
    std::size_t best = actual.features.size();
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < actual.features.size(); ++k) {
      const auto& g = actual.features[k];
      if (used[k] || g.index() != f.index()) continue;
      const auto* pb = placement(g);
      const double d = pa && pb ? std::hypot(pa->location.x - pb->location.x, pa->location.y - pb->location.y) : 0;
      if (d < best_d) best_d = d, best = k;
    }
    if (best == actual.features.size()) {
      out.differences.push_back(id + ": no " + std::string(sn::entity_name(f)) + " read back");
      continue;
    }
    used[best] = true;
    ++out.matched;
    const auto& g = actual.features[best];
    const auto* pb = placement(g);
    const auto ca = centre_of(f, i, stock), cb = centre_of(g, best, stock);
    const double off = std::hypot(ca.x - cb.x, ca.y - cb.y);
    if (off > t.centre) {
      out.differences.push_back(id + ": centre (" + num(ca.x) + ", " + num(ca.y) + ") read back at (" + num(cb.x) + ", " +
                                num(cb.y) + "), " + num(off) + " mm off");
    }
    if (pa && pb) {
      if (std::abs(pa->location.z - pb->location.z) > t.height) {
        out.differences.push_back(id + ": top " + num(pa->location.z) + " read back as " + num(pb->location.z));
      }
    }
    if (std::abs(depth(f) - depth(g)) > t.height) {
      out.differences.push_back(id + ": depth " + num(depth(f)) + " read back as " + num(depth(g)));
    }
    const auto da = dimensions(f), db = dimensions(g);
    if (da.size() != db.size()) {
      out.differences.push_back(id + ": its profile read back as another kind");
    } else {
      for (std::size_t k = 0; k < da.size(); ++k) {
        if (std::abs(da[k].second - db[k].second) > t.dimension) {
          out.differences.push_back(id + ": " + da[k].first + " " + num(da[k].second) + " read back as " + num(db[k].second));
        }
      }
    }
    if (bottom(f) != bottom(g)) out.differences.push_back(id + ": bottom " + bottom(f) + " read back as " + bottom(g));
    const auto oa = operations_of(expected, i), ob = operations_of(actual, best);
    out.operations += static_cast<int>(oa.size());
    for (std::size_t k = 0; k < oa.size(); ++k) {
      if (k >= ob.size()) {
        out.differences.push_back(id + ": operation " + oa[k].entity + " (" + oa[k].tool + ") not read back");
        continue;
      }
      bool same = oa[k].entity == ob[k].entity && oa[k].tool == ob[k].tool;
      if (oa[k].strategy != "$" && !same_directions_impl(oa[k].strategy, ob[k].strategy, t.direction)) same = false;
      if (same) {
        ++out.operations_matched;
      } else {
        out.differences.push_back(id + ": operation " + oa[k].entity + " " + oa[k].tool + " " + oa[k].strategy + " read back as " +
                                  ob[k].entity + " " + ob[k].tool + " " + ob[k].strategy);
      }
    }
    for (std::size_t k = oa.size(); k < ob.size(); ++k) {
      out.differences.push_back(id + ": an extra operation " + ob[k].entity + " " + ob[k].tool + " " + ob[k].strategy);
    }
  }
  for (std::size_t k = 0; k < actual.features.size(); ++k) {
    if (used[k] || std::holds_alternative<sn::ToolpathFeature>(actual.features[k])) continue;
    bool machined = false;
    for (const auto& e : actual.main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) machined = machined || ws->its_feature.index == k;
    }
    if (machined) out.differences.push_back(sn::feature_id(actual.features[k]) + ": an extra " + std::string(sn::entity_name(actual.features[k])) + " read back");
  }
  return out;
}

}  // namespace ncbridge::test_support
