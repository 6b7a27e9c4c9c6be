#include "motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncbridge::toolpath_generator {

namespace {

constexpr double kPi = std::numbers::pi;

Point2 xy(const Point3& p) { return {p.x, p.y}; }

bool same_xy(Point2 a, Point2 b) { return distance(a, b) < 1e-9; }

}  // namespace

MotionBuilder::MotionBuilder(const PartModel& part, PolygonSet centres, double radius, double safe_z, const Options& options)
    : part_(part), centres_(std::move(centres)), radius_(radius), safe_z_(safe_z), options_(options) {
  links_ = centres_.offset(0.001, kArcTolerance);
}

void MotionBuilder::rapid_to(Point3 p) {
  if (std::abs(p.x - at_.x) < 1e-9 && std::abs(p.y - at_.y) < 1e-9 && std::abs(p.z - at_.z) < 1e-9) return;
  motion_.moves.push_back({Move3::Kind::Rapid, p, std::nullopt, 0});
  at_ = p;
}

void MotionBuilder::feed_to(Point3 p, Move3::Kind kind) {
  if (std::abs(p.x - at_.x) < 1e-9 && std::abs(p.y - at_.y) < 1e-9 && std::abs(p.z - at_.z) < 1e-9) return;
  motion_.moves.push_back({kind, p, std::nullopt, 0});
  at_ = p;
}

void MotionBuilder::retract() { rapid_to({at_.x, at_.y, safe_z_}); }

bool MotionBuilder::air_at(Point2 p, double z) {
  auto it = air_.find(z);
  if (it == air_.end()) {
    // Where the disk lies in what is cleared to z, or wholly outside the stock.
    const auto& s = part_.stock();
    material_check::Box2 box = centres_.empty() ? material_check::Box2{s.min[0], s.min[1], s.max[0], s.max[1]} : centres_.box();
    box = grown(box, 2 * radius_);
    it = air_.emplace(z, part_.cleared_at(z, box).offset(-radius_ + 1e-4, kArcTolerance)).first;
  }
  return it->second.contains(p);
}

void MotionBuilder::path(const PlanarCurve& curve, double z, Move3::Kind kind) {
  for (const auto& s : curve.segments) {
    if (const auto* l = std::get_if<LineSegment>(&s)) {
      feed_to({l->b.x, l->b.y, z}, kind);
      continue;
    }
    const auto& a = std::get<ArcSegment>(s);
    const Point2 e = a.end();
    motion_.moves.push_back({kind, {e.x, e.y, z}, a.centre, a.sweep});
    at_ = {e.x, e.y, z};
  }
}

// Moves down from from_z to to_z along the passes, z falling in proportion to the length
// travelled; each move falls at least 0.002 mm (moves within 0.001 mm of one height read as a
// level): runs of short segments become one chord (inside a convex corner by far less than the
// tolerance at ramp slopes).
void MotionBuilder::descend_along(const std::vector<const PlanarCurve*>& passes, double from_z, double to_z) {
  constexpr double kLeastDrop = 0.002;
  double total = 0;
  for (const auto* p : passes) total += p->length();
  const double drop = from_z - to_z;
  double done = 0;
  double pending_z = at_.z;
  bool pending = false;
  Point2 pending_xy{};
  for (std::size_t n = 0; n < passes.size(); ++n) {
    const auto* p = passes[n];
    for (std::size_t k = 0; k < p->segments.size(); ++k) {
      const auto& s = p->segments[k];
      done += material_check::length_of(s);
      const bool last = n + 1 == passes.size() && k + 1 == p->segments.size();
      const double z = last ? to_z : from_z - drop * done / total;
      const Point2 e = material_check::end_of(s);
      if (!pending && at_.z - z >= kLeastDrop) {
        if (const auto* a = std::get_if<ArcSegment>(&s)) {
          motion_.moves.push_back({Move3::Kind::Entry, {e.x, e.y, z}, a->centre, a->sweep});
          at_ = {e.x, e.y, z};
        } else {
          feed_to({e.x, e.y, z}, Move3::Kind::Entry);
        }
        continue;
      }
      pending = true;
      pending_xy = e;
      pending_z = z;
      if (at_.z - pending_z >= kLeastDrop || last) {
        feed_to({pending_xy.x, pending_xy.y, pending_z}, Move3::Kind::Entry);
        pending = false;
      }
    }
  }
  if (pending) feed_to({pending_xy.x, pending_xy.y, pending_z}, Move3::Kind::Entry);
  at_.z = to_z;
  if (!motion_.moves.empty()) motion_.moves.back().end.z = to_z;
}

// Down from from_z to to_z along the cut at the ramp angle: round a loop (as far as needed, or
// whole laps when one is not enough), or back and forth along the start of an open path (an
// even number of passes, so that it ends where the path starts). Returns where it ends.
Point2 MotionBuilder::ramp(const PlanarCurve& cut, double from_z, double to_z) {
  const double drop = from_z - to_z;
  if (drop <= 1e-9) return {at_.x, at_.y};
  const double slope = std::tan(options_.ramp_angle_deg * kPi / 180);
  const double needed = drop / slope;
  const double length = cut.length();
  if (length < 1e-3) {  // nothing to ramp along: straight down
    feed_to({at_.x, at_.y, to_z}, Move3::Kind::Entry);
    return {at_.x, at_.y};
  }
  std::vector<const PlanarCurve*> passes;
  PlanarCurve forward, backward;
  // Round a whole circle a ramp would be a helix about the loop's centre, which reads as a hole
  // milled by interpolation: ramp along its diameter instead.
  const auto* first_arc = cut.closed ? std::get_if<ArcSegment>(&cut.segments.front()) : nullptr;
  const bool circle = first_arc && std::all_of(cut.segments.begin(), cut.segments.end(), [&](const CurveSegment& seg) {
    const auto* a = std::get_if<ArcSegment>(&seg);
    return a && distance(a->centre, first_arc->centre) < 1e-6 && std::abs(a->radius - first_arc->radius) < 1e-6;
  });
  if (circle) {
    const auto& a = *first_arc;
    PlanarCurve diameter;
    const Point2 s = a.start(), o{2 * a.centre.x - s.x, 2 * a.centre.y - s.y};
    diameter.segments.emplace_back(LineSegment{s, o});
    forward = leading_part(diameter, std::min(diameter.length(), std::max(needed / 2, 1e-3)));
    backward = forward.reversed();
    int n = std::max(2, static_cast<int>(std::ceil(needed / forward.length() - 1e-9)));
    if (n % 2) ++n;
    for (int k = 0; k < n; ++k) passes.push_back(k % 2 ? &backward : &forward);
    descend_along(passes, from_z, to_z);
    return {at_.x, at_.y};
  }
  if (cut.closed) {
    if (needed <= length) {
      forward = leading_part(cut, needed);
      passes.push_back(&forward);
    } else {
      const int laps = static_cast<int>(std::ceil(needed / length - 1e-9));
      for (int k = 0; k < laps; ++k) passes.push_back(&cut);
    }
  } else {
    forward = leading_part(cut, std::min(length, std::max(needed / 2, 1e-3)));
    backward = forward.reversed();
    int n = std::max(2, static_cast<int>(std::ceil(needed / forward.length() - 1e-9)));
    if (n % 2) ++n;
    for (int k = 0; k < n; ++k) passes.push_back(k % 2 ? &backward : &forward);
  }
  descend_along(passes, from_z, to_z);
  return {at_.x, at_.y};
}

Point2 MotionBuilder::approach(Point2 p, double z, double material_above, const PlanarCurve* entry) {
  if (!started_) {
    started_ = true;
    at_ = {p.x, p.y, safe_z_};
    motion_.start = at_;
  } else if (!same_xy(xy(at_), p) || at_.z > safe_z_) {
    retract();
    rapid_to({p.x, p.y, safe_z_});
  }
  const double top = std::min(material_above, part_.material_top(p, radius_));
  if (air_at(p, z)) {
    // Air all the way down: rapid to just above the level, feed the rest.
    const double above = std::isfinite(top) ? std::max(top, z) + options_.clearance : z + options_.clearance;
    rapid_to({p.x, p.y, std::min(safe_z_, above)});
    feed_to({p.x, p.y, z});
    return p;
  }
  rapid_to({p.x, p.y, std::min(safe_z_, top + options_.clearance)});
  feed_to({p.x, p.y, top});
  if (entry) return ramp(*entry, top, z);
  feed_to({p.x, p.y, z}, Move3::Kind::Entry);
  return p;
}

void MotionBuilder::level(double z, double material_above, const std::vector<Cut>& cuts) {
  for (const auto& cut : cuts) {
    if (cut.path.segments.empty()) continue;
    PlanarCurve c = cut.path;
    if (c.closed) {
      // Start a loop where the cutter is (or, entering, where it finds air).
      Point2 from = xy(at_);
      if (!started_ || std::abs(at_.z - z) > 1e-9) {
        const std::size_t n = c.segments.size(), step = std::max<std::size_t>(1, n / 32);
        for (std::size_t k = 0; k < n; k += step) {
          const Point2 q = material_check::start_of(c.segments[k]);
          if (air_at(q, z)) {
            from = q;
            break;
          }
        }
      }
      c = loop_from(c, from);
    }
    const Point2 start = material_check::start_of(c.segments.front());
    const bool here = started_ && std::abs(at_.z - z) < 1e-9;
    const bool above = started_ && at_.z > z + 1e-9 && at_.z <= material_above + 1e-9;
    Point2 entered = start;
    if ((here || above) && !cut.lift_before && segment_inside(links_, xy(at_), start)) {
      feed_to({start.x, start.y, at_.z});
      if (above) {
        if (air_at(start, z)) feed_to({start.x, start.y, z});
        else entered = ramp(c, at_.z, z);
      }
    } else {
      // An open path that starts in material: lead in along it from where there is air (outside
      // the stock, or cut already), when the clearing area reaches that far.
      if (!c.closed && !air_at(start, z)) {
        const Point2 next = material_check::end_of(c.segments.front());
        const auto& s0 = c.segments.front();
        Point2 back{start.x - next.x, start.y - next.y};
        if (const auto* a = std::get_if<ArcSegment>(&s0)) {
          const double sign = a->sweep > 0 ? -1 : 1;
          back = {-std::sin(a->start_angle) * sign, std::cos(a->start_angle) * sign};
        }
        const double n = std::hypot(back.x, back.y);
        if (n > 1e-12) {
          back = {back.x / n, back.y / n};
          for (double d = radius_ / 2; d <= 6 * radius_ + 20; d += radius_ / 2) {
            const Point2 q{start.x + back.x * d, start.y + back.y * d};
            if (!segment_inside(links_, q, start)) break;
            if (air_at(q, z)) {
              PlanarCurve lead;
              lead.segments.emplace_back(LineSegment{q, start});
              lead.segments.insert(lead.segments.end(), c.segments.begin(), c.segments.end());
              c = std::move(lead);
              break;
            }
          }
        }
      }
      entered = approach(material_check::start_of(c.segments.front()), z, material_above, &c);
    }
    // A loop entered by a partial lap is cut whole from where the ramp reached the level.
    if (c.closed && distance(entered, material_check::start_of(c.segments.front())) > 1e-9) {
      c = loop_from(c, entered);
      feed_to({material_check::start_of(c.segments.front()).x, material_check::start_of(c.segments.front()).y, z});
    }
    path(c, z, Move3::Kind::Feed);
  }
}

void MotionBuilder::helix_to(Point2 centre, double z, double sweep_per_turn, int turns) {
  const double from = at_.z;
  for (int k = 1; k <= turns; ++k) {
    const double zk = from + (z - from) * k / turns;
    motion_.moves.push_back({Move3::Kind::Feed, {at_.x, at_.y, zk}, centre, sweep_per_turn});
  }
  at_.z = z;
}

Motion3 MotionBuilder::take() {
  retract();
  Motion3 out = std::move(motion_);
  motion_ = {};
  started_ = false;
  return out;
}

}  // namespace ncbridge::toolpath_generator
