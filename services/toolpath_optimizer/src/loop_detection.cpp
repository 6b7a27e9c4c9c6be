// Repeated layers as loops (loop_detector.hpp).
#include <cmath>

#include "ncbridge/interpreter/canon_printer.hpp"
#include "ncbridge/toolpath_optimizer/loop_detector.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

bool is_comment(const Element& e) {
  if (const auto* t = std::get_if<TextLine>(&e.item)) return t->role == LineRole::Comment || t->role == LineRole::Blank;
  if (const auto* c = std::get_if<canonical::Call>(&e.item)) return std::holds_alternative<canonical::Comment>(c->data);
  return false;
}

}  // namespace

LoopDetector::LoopDetector(const LoopOptions& options, ElementSink& out) : options_(options), out_(out) {}

void LoopDetector::element(Element&& e) {
  if (const auto* m = std::get_if<Motion>(&e.item)) {
    if (!z_known_ || !(std::abs(m->end.z - z_) <= 1e-9)) {
      // A new layer: what came after the last motion (a layer comment, a fan speed) opens it.
      Layer next;
      next.z = m->end.z;
      if (current_.has_motion) {
        const auto tail = current_.elements.begin() + static_cast<std::ptrdiff_t>(last_motion_ + 1);
        next.elements.assign(std::make_move_iterator(tail), std::make_move_iterator(current_.elements.end()));
        current_.elements.erase(tail, current_.elements.end());
      } else {
        next.elements = std::move(current_.elements);
      }
      if (!current_.elements.empty()) close_layer();
      current_ = std::move(next);
      z_ = m->end.z;
      z_known_ = true;
    }
    current_.has_motion = true;
    last_motion_ = current_.elements.size();
  }
  current_.elements.push_back(std::move(e));
}

void LoopDetector::end() {
  if (current_.has_motion && last_motion_ + 1 < current_.elements.size()) {
    // What follows the last motion (an end script's commands) is not part of the last layer.
    Layer tail;
    const auto from = current_.elements.begin() + static_cast<std::ptrdiff_t>(last_motion_ + 1);
    tail.elements.assign(std::make_move_iterator(from), std::make_move_iterator(current_.elements.end()));
    current_.elements.erase(from, current_.elements.end());
    close_layer();
    current_ = std::move(tail);
  }
  if (!current_.elements.empty()) close_layer();
  settle(true);
  out_.end();
}

void LoopDetector::close_layer() {
  pending_.push_back(std::move(current_));
  current_ = Layer{};
  settle(false);
}

bool LoopDetector::same_layer(const Layer& a, const Layer& b, double shift) const {
  if (a.elements.size() != b.elements.size() || !a.has_motion) return false;
  const double tol = options_.position_match;
  auto near = [tol](double x, double y) { return std::abs(x - y) <= tol; };
  auto same_point = [&](const Vec3& p, const Vec3& q) { return near(p.x, q.x) && near(p.y, q.y) && near(p.z + shift, q.z); };
  bool first_motion = true;
  std::string ca, cb;
  for (std::size_t i = 0; i < a.elements.size(); ++i) {
    const Element& x = a.elements[i];
    const Element& y = b.elements[i];
    if (x.item.index() != y.item.index()) return false;
    if (const auto* p = std::get_if<Motion>(&x.item)) {
      const auto& q = std::get<Motion>(y.item);
      if (p->kind != q.kind || p->feed != q.feed || p->units != q.units || p->rotary != q.rotary ||
          p->rotary_moves != q.rotary_moves || p->start_known != q.start_known || !p->start_known) {
        return false;
      }
      if (!same_point(p->end, q.end)) return false;
      if (!(first_motion && p->kind != MotionKind::Arc) && !same_point(p->start, q.start)) return false;
      if (std::abs(p->extrusion - q.extrusion) > options_.extrusion_match) return false;
      if (p->kind == MotionKind::Arc) {
        const ArcGeometry& g = p->arc;
        const ArcGeometry& h = q.arc;
        if (g.plane != h.plane || g.ccw != h.ccw || g.extra_turns != h.extra_turns) return false;
        const double df = g.plane == canonical::Plane::XZ ? shift : 0;
        const double ds = g.plane == canonical::Plane::YZ ? shift : 0;
        if (!near(g.first_centre + df, h.first_centre) || !near(g.second_centre + ds, h.second_centre)) return false;
      }
      first_motion = false;
    } else if (const auto* t = std::get_if<TextLine>(&x.item)) {
      if (!(is_comment(x) && is_comment(y)) && t->text != std::get<TextLine>(y.item).text) return false;
    } else if (const auto* c = std::get_if<canonical::Call>(&x.item)) {
      if (is_comment(x) && is_comment(y)) continue;
      interpreter::CanonPrinter::format_call(c->data, ca);
      interpreter::CanonPrinter::format_call(std::get<canonical::Call>(y.item).data, cb);
      if (ca != cb) return false;
    } else {
      return false;
    }
  }
  return true;
}

void LoopDetector::emit_layer(Layer&& layer) {
  for (auto& e : layer.elements) out_.element(std::move(e));
}

void LoopDetector::emit_loop() {
  Loop loop;
  for (auto& layer : body_) {
    for (auto& e : layer.elements) loop.body.push_back(std::move(e));
  }
  loop.count = count_;
  loop.z_shift = shift_;
  ++stats_.loops;
  out_.element(Element{std::move(loop)});
  body_.clear();
  count_ = 0;
}

void LoopDetector::settle(bool at_end) {
  const std::size_t periods = options_.max_period;
  for (;;) {
    if (count_ > 0) {
      // Growing a loop: do the next layers repeat the body once more?
      const std::size_t p = body_.size();
      if (pending_.size() < p) {
        if (!at_end) return;
        emit_loop();
        continue;
      }
      bool repeats = true;
      for (std::size_t i = 0; i < p && repeats; ++i) repeats = same_layer(body_[i], pending_[i], shift_ * count_);
      if (!repeats) {
        emit_loop();
        continue;
      }
      ++count_;
      stats_.layers_in_loops += p;
      for (std::size_t i = 0; i < p; ++i) pending_.pop_front();
      continue;
    }
    if (pending_.empty()) return;
    if (pending_.size() < 2 * periods && !at_end) return;
    bool started = false;
    for (std::size_t p = 1; p <= periods && 2 * p <= pending_.size() && !started; ++p) {
      const double shift = pending_[p].z - pending_[0].z;
      if (!std::isfinite(shift)) continue;
      bool repeats = true;
      for (std::size_t i = 0; i < p && repeats; ++i) repeats = same_layer(pending_[i], pending_[p + i], shift);
      if (!repeats) continue;
      for (std::size_t i = 0; i < p; ++i) {
        body_.push_back(std::move(pending_.front()));
        pending_.pop_front();
      }
      for (std::size_t i = 0; i < p; ++i) pending_.pop_front();
      count_ = 2;
      shift_ = shift;
      stats_.layers_in_loops += p;
      started = true;
    }
    if (!started) {
      emit_layer(std::move(pending_.front()));
      pending_.pop_front();
    }
  }
}

}  // namespace ncbridge::toolpath_optimizer
