// Canonical calls to elements and back (canonical_bridge.hpp).
#include "ncbridge/toolpath_optimizer/canonical_bridge.hpp"

#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

Vec3 xyz(const canonical::Pose& p) { return {p.x, p.y, p.z}; }
std::array<double, 6> others(const canonical::Pose& p) { return {p.a, p.b, p.c, p.u, p.v, p.w}; }

canonical::Pose pose(const Vec3& p, const std::array<double, 6>& r) {
  return {p.x, p.y, p.z, r[0], r[1], r[2], r[3], r[4], r[5]};
}

}  // namespace

void CanonicalFrontEnd::source_file(std::uint32_t, std::string_view) {}

void CanonicalFrontEnd::offset_changed(const canonical::Pose& total) {
  // The same machine position in the new program frame.
  const canonical::Pose before{g5x_.x + g92_.x + tool_.x, g5x_.y + g92_.y + tool_.y, g5x_.z + g92_.z + tool_.z};
  position_.x -= total.x - before.x;
  position_.y -= total.y - before.y;
  position_.z -= total.z - before.z;
}

void CanonicalFrontEnd::motion(const canonical::Call& c, MotionKind kind, const canonical::Pose& end) {
  Motion m;
  m.kind = kind;
  m.start = position_;
  m.end = xyz(end);
  m.rotary = others(end);
  m.rotary_moves = m.rotary != rotary_;
  m.feed = kind == MotionKind::Traverse ? 0 : feed_;
  m.units = units_;
  m.source = c.source;
  m.start_known = known_;
  m.arc.plane = plane_;
  // Keep what a cycle made, and moves whose timing is per block.
  m.keep = c.cycle.has_value() || (kind != MotionKind::Traverse && feed_mode_ != 0);
  position_ = m.end;
  rotary_ = m.rotary;
  known_ = true;
  ++motions_;
  out_.element(Element{std::move(m)});
}

void CanonicalFrontEnd::call(const canonical::Call& c) {
  ++calls_;
  if (const auto* t = std::get_if<canonical::StraightTraverse>(&c.data)) {
    motion(c, MotionKind::Traverse, t->end);
    return;
  }
  if (const auto* f = std::get_if<canonical::StraightFeed>(&c.data)) {
    motion(c, MotionKind::Line, f->end);
    return;
  }
  if (const auto* a = std::get_if<canonical::ArcFeed>(&c.data)) {
    const Vec3 end = from_plane({a->first_end, a->second_end, a->axis_end_point}, plane_);
    Motion m;
    m.kind = MotionKind::Arc;
    m.start = position_;
    m.end = end;
    m.rotary = {a->a, a->b, a->c, a->u, a->v, a->w};
    m.rotary_moves = m.rotary != rotary_;
    m.feed = feed_;
    m.units = units_;
    m.source = c.source;
    m.start_known = known_;
    m.arc.plane = plane_;
    m.arc.first_centre = a->first_axis;
    m.arc.second_centre = a->second_axis;
    m.arc.ccw = a->rotation > 0;
    m.arc.extra_turns = static_cast<std::uint32_t>(std::abs(a->rotation) > 1 ? std::abs(a->rotation) - 1 : 0);
    m.keep = true;
    position_ = end;
    rotary_ = m.rotary;
    known_ = true;
    ++motions_;
    ++arcs_;
    out_.element(Element{std::move(m)});
    return;
  }
  // Everything else rides along; a few calls change how later motions are to be read.
  if (const auto* r = std::get_if<canonical::SetFeedRate>(&c.data)) feed_ = r->rate;
  else if (const auto* fm = std::get_if<canonical::SetFeedMode>(&c.data)) feed_mode_ = fm->mode;
  else if (const auto* u = std::get_if<canonical::UseLengthUnits>(&c.data)) {
    // The interpreter re-expresses positions in the new units.
    const double f = u->units == units_ ? 1.0 : (u->units == canonical::Units::Inches ? 1 / 25.4 : 25.4);
    position_ = f * position_;
    units_ = u->units;
  } else if (const auto* p = std::get_if<canonical::SelectPlane>(&c.data)) plane_ = p->plane;
  else if (const auto* g = std::get_if<canonical::SetG5xOffset>(&c.data)) {
    canonical::Pose total = g->offset;
    total.x += g92_.x + tool_.x, total.y += g92_.y + tool_.y, total.z += g92_.z + tool_.z;
    offset_changed(total);
    g5x_ = g->offset;
  } else if (const auto* g92 = std::get_if<canonical::SetG92Offset>(&c.data)) {
    canonical::Pose total = g92->offset;
    total.x += g5x_.x + tool_.x, total.y += g5x_.y + tool_.y, total.z += g5x_.z + tool_.z;
    offset_changed(total);
    g92_ = g92->offset;
  } else if (const auto* tl = std::get_if<canonical::UseToolLengthOffset>(&c.data)) {
    canonical::Pose total = tl->offset;
    total.x += g5x_.x + g92_.x, total.y += g5x_.y + g92_.y, total.z += g5x_.z + g92_.z;
    offset_changed(total);
    tool_ = tl->offset;
  } else if (std::holds_alternative<canonical::SetXyRotation>(c.data)) {
    known_ = false;
  } else if (std::holds_alternative<canonical::StraightProbe>(c.data) ||
             std::holds_alternative<canonical::RigidTap>(c.data)) {
    known_ = false;  // where a probe stops (or a tap returns to) is the machine's business
  }
  out_.element(Element{c});
}

void to_canonical(const Element& e, canonical::Sink& sink) {
  if (const auto* m = std::get_if<Motion>(&e.item)) {
    canonical::Call c;
    c.source = m->source;
    if (m->kind == MotionKind::Traverse) {
      c.data = canonical::StraightTraverse{pose(m->end, m->rotary)};
    } else if (m->kind == MotionKind::Line) {
      c.data = canonical::StraightFeed{pose(m->end, m->rotary)};
    } else {
      const PlanePoint end = to_plane(m->end, m->arc.plane);
      const int turns = 1 + static_cast<int>(m->arc.extra_turns);
      c.data = canonical::ArcFeed{end.first, end.second, m->arc.first_centre, m->arc.second_centre,
                                  m->arc.ccw ? turns : -turns, end.normal, m->rotary[0], m->rotary[1],
                                  m->rotary[2], m->rotary[3], m->rotary[4], m->rotary[5]};
    }
    sink.call(c);
  } else if (const auto* c = std::get_if<canonical::Call>(&e.item)) {
    sink.call(*c);
  } else if (const auto* t = std::get_if<TextLine>(&e.item)) {
    if (t->role == LineRole::Blank) return;
    std::string text = t->text;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    canonical::Call comment;
    comment.source.line = t->line;
    comment.data = canonical::Comment{text};
    sink.call(comment);
  }
}

}  // namespace ncbridge::toolpath_optimizer
