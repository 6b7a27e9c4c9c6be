// The stage (optimizer.hpp): collects runs, fits them, emits the result in order.
#include "ncbridge/toolpath_optimizer/optimizer.hpp"

#include <algorithm>
#include <cmath>

#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

// Extruding, travelling or retracting on the way (a wipe): never one move across two of them.
int sign(double e) { return e > 0 ? 1 : e < 0 ? -1 : 0; }

bool rides_along(const Element& e) {
  const auto* t = std::get_if<TextLine>(&e.item);
  return t && (t->role == LineRole::Comment || t->role == LineRole::Blank);
}

}  // namespace

Optimizer::Optimizer(const OptimizerOptions& options, ElementSink& out) : options_(options), out_(out) {}

bool Optimizer::fittable(const Motion& m) const {
  return m.kind != MotionKind::Arc && m.start_known && !m.keep && !m.rotary_moves && !(m.start == m.end);
}

bool Optimizer::continues_run(const Motion& m) const {
  const Motion& first = run_.front();
  return m.kind == first.kind && m.feed == first.feed && m.units == first.units && m.arc.plane == first.arc.plane &&
         sign(m.extrusion) == sign(first.extrusion) && m.printer.relative_e == first.printer.relative_e &&
         m.rotary == first.rotary && m.start == run_.back().end && run_.size() < options_.max_run;
}

void Optimizer::emit(Element&& e) {
  if (std::holds_alternative<Motion>(e.item)) ++stats_.motions_out;
  out_.element(std::move(e));
}

void Optimizer::true_arc(Motion& m) {
  const PlanePoint s = to_plane(m.start, m.arc.plane), e = to_plane(m.end, m.arc.plane);
  const double r1 = std::hypot(s.first - m.arc.first_centre, s.second - m.arc.second_centre);
  const double r2 = std::hypot(e.first - m.arc.first_centre, e.second - m.arc.second_centre);
  const double du = e.first - s.first, dv = e.second - s.second, chord = std::hypot(du, dv);
  if (std::abs(r1 - r2) <= 1e-12 * std::max(r1, r2) || chord <= 0) return;
  const double mu = (s.first + e.first) / 2, mv = (s.second + e.second) / 2;
  const double nu = -dv / chord, nv = du / chord;
  const double t = (m.arc.first_centre - mu) * nu + (m.arc.second_centre - mv) * nv;
  const double cu = mu + t * nu, cv = mv + t * nv;
  // The spiral the control would move and the true arc, compared point by point at equal
  // fractions (an upper bound of the distance between the two paths).
  Motion recentred = m;
  recentred.arc.first_centre = cu;
  recentred.arc.second_centre = cv;
  const ArcPath spiral = resolve_arc(m), circle = resolve_arc(recentred);
  if (std::abs(spiral.sweep - circle.sweep) > kPi / 2) return;  // not the same arc any more
  double apart = 0;
  constexpr int kSamples = 64;
  for (int i = 1; i < kSamples; ++i) {
    const double f = static_cast<double>(i) / kSamples;
    apart = std::max(apart, distance(spiral.at(f), circle.at(f)));
  }
  const double unit = m.units == canonical::Units::Inches ? 1 / 25.4 : 1.0;
  if (apart > options_.tolerance_mm * unit / 2) return;
  m = std::move(recentred);
  ++stats_.arcs_recentred;
}

void Optimizer::element(Element&& e) {
  if (auto* m = std::get_if<Motion>(&e.item)) {
    ++stats_.motions_in;
    if (options_.true_arcs && m->kind == MotionKind::Arc && m->start_known) true_arc(*m);
    if (fittable(*m)) {
      if (!run_.empty() && !continues_run(*m)) flush();
      if (run_.empty()) vertices_.push_back({m->start, 0.0, 0.0});
      const FitVertex& last = vertices_.back();
      vertices_.push_back({m->end, last.e + m->extrusion, last.along + distance(m->start, m->end)});
      run_.push_back(std::move(*m));
      return;
    }
  }
  if (!run_.empty() && rides_along(e)) {
    riders_.emplace_back(run_.size(), std::move(e));
    return;
  }
  flush();
  emit(std::move(e));
}

void Optimizer::end() {
  flush();
  out_.end();
}

void Optimizer::flush() {
  if (run_.empty()) return;
  std::size_t rider = 0;
  auto emit_riders = [&](std::size_t up_to) {
    for (; rider < riders_.size() && riders_[rider].first <= up_to; ++rider) emit(std::move(riders_[rider].second));
  };
  ++stats_.runs;
  const Motion& first = run_.front();
  const double unit = first.units == canonical::Units::Inches ? 1 / 25.4 : 1.0;
  FitOptions fit;
  fit.tolerance = options_.tolerance_mm * unit;
  fit.margin = options_.margin_mm * unit;
  fit.min_segment = options_.min_segment_mm * unit;
  fit.arcs = options_.arcs && first.kind == MotionKind::Line && (options_.travel_arcs || first.extrusion > 0) &&
             (!options_.xy_arcs_only || first.arc.plane == canonical::Plane::XY);
  fit.helical = options_.helical;
  fit.max_radius = options_.max_radius_mm * unit;
  fit.min_arc_radius = options_.min_arc_radius_mm * unit;
  fit.extrusion_rate_variance = options_.extrusion_rate_variance;
  fit.plane = first.arc.plane;
  int decimals = options_.centre_decimals;
  if (decimals >= 0 && first.units == canonical::Units::Inches) ++decimals;  // one more in inches
  if (decimals < 0) {
    int xyz = 0;
    for (const Motion& m : run_) xyz = std::max<int>(xyz, m.printer.xyz_decimals);
    decimals = std::clamp(xyz + 1, 3, 6);
  }
  fit.centre_resolution = std::pow(10.0, -decimals);

  fitted_.clear();
  FitStats fs;
  fit_polyline(vertices_, fit, fitted_, fs, workspace_);
  stats_.arcs += fs.arcs;
  stats_.lines_merged += fs.lines_merged;
  stats_.folded += fs.folded;

  for (const FittedMove& f : fitted_) {
    if (f.last == f.first + 1) {
      emit(Element{std::move(run_[f.first])});
      emit_riders(f.last);
      continue;
    }
    const Motion& a = run_[f.first];
    const Motion& b = run_[f.last - 1];
    Motion m;
    m.kind = f.arc ? MotionKind::Arc : a.kind;
    m.start = vertices_[f.first].p;
    m.end = vertices_[f.last].p;
    m.arc = f.arc ? f.geometry : a.arc;
    m.feed = a.feed;
    m.extrusion = vertices_[f.last].e - vertices_[f.first].e;
    m.rotary = a.rotary;
    m.units = a.units;
    m.source = a.source;
    m.blocks = 0;
    bool has_e = false;
    std::uint8_t xyz = 0, e = 0;
    for (std::size_t i = f.first; i < f.last; ++i) {
      m.blocks += run_[i].blocks;
      has_e = has_e || run_[i].printer.has_e;
      xyz = std::max(xyz, run_[i].printer.xyz_decimals);
      e = std::max(e, run_[i].printer.e_decimals);
    }
    m.printer.e_position = b.printer.e_position;
    m.printer.xyz_decimals = xyz;
    m.printer.e_decimals = e;
    m.printer.relative_e = a.printer.relative_e;
    m.printer.has_e = has_e && m.extrusion != 0;
    m.printer.has_f = a.printer.has_f;
    m.printer.crlf = a.printer.crlf;
    emit(Element{std::move(m)});
    emit_riders(f.last);
  }
  emit_riders(run_.size());
  riders_.clear();
  run_.clear();
  vertices_.clear();
}

}  // namespace ncbridge::toolpath_optimizer
