// The deviation checker (deviation_checker.hpp).
#include "ncbridge/toolpath_optimizer/deviation_checker.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

constexpr double kCertifySlack = 1e-6;  // rounding of the arithmetic, not of the geometry

bool is_point(const PathPiece& p) { return p.kind != MotionKind::Arc && distance(p.start, p.end) <= 1e-12; }

Motion as_motion(const PathPiece& p) {
  Motion m;
  m.kind = p.kind;
  m.start = p.start;
  m.end = p.end;
  m.arc = p.arc;
  return m;
}

// A piece ready for distance queries.
struct Shape {
  bool arc = false;
  Vec3 a, b;
  ArcPath path;
  double length = 0;

  explicit Shape(const PathPiece& p) : arc(p.kind == MotionKind::Arc), a(p.start), b(p.end) {
    if (arc) {
      path = resolve_arc(as_motion(p));
      length = path.length();
    } else {
      length = distance(a, b);
    }
  }
  Vec3 at(double f) const { return arc ? path.at(f) : a + f * (b - a); }
  // Where along the shape (0..1) the point nearest q is, about.
  double fraction_of(Vec3 q) const {
    if (!arc) {
      const Vec3 d = b - a;
      const double l2 = dot(d, d);
      return l2 > 0 ? std::clamp(dot(q - a, d) / l2, 0.0, 1.0) : 0.0;
    }
    if (path.sweep == 0) return 0;
    const PlanePoint qp = to_plane(q, path.plane);
    const double angle = std::atan2(qp.second - path.centre_second, qp.first - path.centre_first);
    double f = (angle - path.start_angle) / path.sweep;
    const double turn = 2 * kPi / std::abs(path.sweep);
    f -= std::floor(f / turn) * turn;
    double best = f, best_d = 1e300;
    for (; f <= 1.0; f += turn) {
      const double d = distance(q, at(f));
      if (d < best_d) best_d = d, best = f;
    }
    if (distance(q, a) < best_d) best = 0, best_d = distance(q, a);
    if (distance(q, b) < best_d) best = 1;
    return best;
  }
  // How far the piece between f0 and f1 strays from its chord, at most (the same fraction of
  // each compared: fit.hpp).
  double chord_deviation(double f0, double f1) const {
    if (!arc) return 0;
    const double half = std::abs(path.sweep) * (f1 - f0) / 2;
    const double c1 = 1 - std::cos(half), c2 = half - std::sin(half);
    return std::max(path.start_radius, path.end_radius) * std::sqrt(c1 * c1 + c2 * c2) +
           std::abs(path.end_radius - path.start_radius) * (f1 - f0);
  }
  // Distance from q to a point of the shape near q (exact for lines and plane arcs).
  double distance_from(Vec3 q) const {
    if (!arc) return distance_to_segment(q, a, b);
    double best = std::min(distance(q, a), distance(q, b));
    const PlanePoint qp = to_plane(q, path.plane);
    const double angle = std::atan2(qp.second - path.centre_second, qp.first - path.centre_first);
    if (path.sweep == 0) return best;
    double f = (angle - path.start_angle) / path.sweep;
    const double turn = 2 * kPi / std::abs(path.sweep);
    // Every fraction with the query's angle.
    f -= std::floor(f / turn) * turn;
    for (; f <= 1.0; f += turn) best = std::min(best, distance(q, at(f)));
    return best;
  }
};

bool same_arc(const PathPiece& a, const PathPiece& b) {
  return a.start == b.start && a.end == b.end && a.arc.plane == b.arc.plane && a.arc.ccw == b.arc.ccw &&
         a.arc.extra_turns == b.arc.extra_turns && std::abs(a.arc.first_centre - b.arc.first_centre) < 1e-9 &&
         std::abs(a.arc.second_centre - b.arc.second_centre) < 1e-9;
}

// The largest distance from points along `shape` to whatever `distance` measures, sampled at
// most `step` apart where it comes near the band (farther apart where it stays well inside).
// Between two samples d1, d2 at h apart no point is farther than (d1 + d2 + h) / 2 (distance is
// 1-Lipschitz along the path); an interval where that exceeds the band is halved until it does
// not, to the band plus kCertifySlack, else `left_band` is set. `largest` gets the largest
// sampled distance.
template <typename Distance>
void sweep(const Shape& shape, Distance&& distance, double tol, double step, double& largest, bool& left_band) {
  auto at_length = [&](double s) { return shape.at(shape.length > 0 ? std::min(1.0, s / shape.length) : 0.0); };
  const double certified = tol + kCertifySlack;
  double previous = distance(at_length(0));
  largest = std::max(largest, previous);
  long budget = 200000;
  auto certify = [&](auto&& self, double s0, double d0, double s1, double d1, int depth) -> void {
    if ((d0 + d1 + (s1 - s0)) / 2 <= certified) return;
    if (d0 > certified || d1 > certified || depth > 40 || --budget < 0) {
      left_band = true;
      return;
    }
    const double sm = (s0 + s1) / 2;
    const double dm = distance(at_length(sm));
    largest = std::max(largest, dm);
    self(self, s0, d0, sm, dm, depth + 1);
    self(self, sm, dm, s1, d1, depth + 1);
  };
  for (double s = 0; s < shape.length;) {
    const double floor_level = std::max(largest, tol / 2);
    const double h = std::min(std::max(step, floor_level - previous), shape.length - s);
    const double d = distance(at_length(s + h));
    if (!left_band) certify(certify, s, previous, s + h, d, 0);
    s += h;
    largest = std::max(largest, d);
    previous = d;
  }
}

}  // namespace

namespace {

template <typename Each>
void add_pieces(const Element& e, double z_shift, Each& each) {
  if (const auto* m = std::get_if<Motion>(&e.item)) {
    if (!m->start_known) return;
    // In mm whatever the program's units.
    const double k = m->units == canonical::Units::Inches ? 25.4 : 1.0;
    PathPiece p;
    p.kind = m->kind;
    p.start = k * m->start;
    p.end = k * m->end;
    p.start.z += k * z_shift;
    p.end.z += k * z_shift;
    p.arc = m->arc;
    p.arc.first_centre *= k;
    p.arc.second_centre *= k;
    if (p.kind == MotionKind::Arc && z_shift != 0) {
      if (p.arc.plane == canonical::Plane::YZ) p.arc.second_centre += k * z_shift;
      if (p.arc.plane == canonical::Plane::XZ) p.arc.first_centre += k * z_shift;
    }
    p.extrusion = k * m->extrusion;
    p.line = m->source.line;
    if (is_point(p) && p.extrusion == 0) return;  // moves nothing
    each(p);
  } else if (const auto* loop = std::get_if<Loop>(&e.item)) {
    for (std::uint32_t i = 0; i < loop->count; ++i) {
      for (const auto& inner : loop->body) add_pieces(inner, z_shift + i * loop->z_shift, each);
    }
  }
}

}  // namespace

void path_pieces(const Element& e, const std::function<void(const PathPiece&)>& each) { add_pieces(e, 0.0, each); }

void PathRecorder::element(Element&& e) {
  auto each = [this](const PathPiece& p) { pieces.push_back(p); };
  add_pieces(e, 0.0, each);
}

void CheckerFeed::element(Element&& e) {
  auto each = [this](const PathPiece& p) {
    if (output_) checker_.output(p);
    else checker_.input(p);
  };
  add_pieces(e, 0.0, each);
}

bool DeviationChecker::check_next(bool final) {
  const PathPiece& o = output_.front();
  const double tol = options_.tolerance;
  const double step = tol / 20;
  std::size_t i = 0;  // next input piece
  if (is_point(o)) {
    // A filament-only move: the next one of the input.
    while (i < input_.size() && is_point(input_[i]) && input_[i].extrusion == 0) ++i;
    if (i >= input_.size() && !final) return false;
    if (i >= input_.size() || !is_point(input_[i])) {
      problem("output " + where(o) + ": a filament-only move where the input has " +
              (i < input_.size() ? "a path move at " + where(input_[i]) : std::string("nothing")));
      return stop();
    }
    const double err = std::abs(o.extrusion - input_[i].extrusion);
    report_.extrusion_error = std::max(report_.extrusion_error, err);
    if (err > options_.extrusion_tolerance + 1e-6 * std::abs(input_[i].extrusion)) {
      problem("output " + where(o) + ": filament move of " + std::to_string(o.extrusion) + " for " +
              std::to_string(input_[i].extrusion) + " at input line " + std::to_string(input_[i].line));
    }
    consume(i + 1);
    return true;
  }
  // The span: input pieces from where the output piece starts to where it ends.
  while (i < input_.size() && is_point(input_[i]) && input_[i].extrusion == 0) ++i;
  if (i >= input_.size()) {
    if (!final) return false;
    problem("output " + where(o) + ": the input path has ended");
    return stop();
  }
  if (distance(input_[i].start, o.start) > options_.vertex_match) {
    problem("output " + where(o) + " starts where the input is not (input " + where(input_[i]) + ")");
    return stop();
  }
  std::size_t k = i;
  bool found = false, crossed_filament_move = false;
  for (; k < input_.size(); ++k) {
    if (is_point(input_[k])) {
      if (input_[k].extrusion != 0) crossed_filament_move = true;
      continue;
    }
    const double d = distance(input_[k].end, o.end);
    if (d <= options_.vertex_match) {
      // Of input vertices in a row that all match (closer together than the written digits),
      // the closest. A closed output piece (a full circle) ends where it starts: the span is
      // never empty.
      // The row may go on in input not read yet: wait for it.
      double best = d;
      std::size_t next = k + 1;
      for (; next < input_.size() && !is_point(input_[next]); ++next) {
        const double dn = distance(input_[next].end, o.end);
        if (dn > options_.vertex_match || dn >= best) break;
        best = dn;
        k = next;
      }
      if (next == input_.size() && !final) return false;
      found = true;
      break;
    }
  }
  if (!found) {
    if (!final) return false;
    problem("output " + where(o) + " ends at no later input vertex (input from line " + std::to_string(input_[i].line) + ")");
    return stop();
  }
  if (crossed_filament_move) problem("output " + where(o) + " runs across a filament-only move of the input");
  const std::size_t span_end = k + 1;
  ++report_.spans;

  const Shape out(o);
  double in_to_out = 0, out_to_in = 0, e_in = 0;
  std::vector<Shape> span;
  span.reserve(span_end - i);
  for (std::size_t j = i; j < span_end; ++j) {
    if (is_point(input_[j])) continue;
    e_in += input_[j].extrusion;
    span.emplace_back(input_[j]);
  }
  bool left_band = false;
  // A motion passed through unchanged is its own output.
  const PathPiece* only = nullptr;
  for (std::size_t j = i; j < span_end; ++j) {
    if (is_point(input_[j])) continue;
    only = only ? &o : &input_[j];
  }
  const bool unchanged = only != &o && only->kind == o.kind && only->start == o.start && only->end == o.end &&
                         (o.kind != MotionKind::Arc || same_arc(o, *only));
  if (!unchanged) {
    // Input to output: the span's vertices, and points along its arcs.
    in_to_out = std::max(in_to_out, out.distance_from(span.front().a));
    for (const Shape& s : span) {
      if (!s.arc) in_to_out = std::max(in_to_out, out.distance_from(s.b));
      else sweep(s, [&](Vec3 p) { return out.distance_from(p); }, tol, step, in_to_out, left_band);
    }
    // Output to input: along the output piece, each point against the input pieces near the
    // one nearest the previous point (both directions walk the input in order).
    std::size_t near = 0;
    auto nearest_in = [&](Vec3 p, std::size_t lo, std::size_t hi) {
      double best = 1e300;
      for (std::size_t j = lo; j < hi; ++j) {
        const double d = span[j].distance_from(p);
        if (d < best) best = d, near = j;
      }
      return best;
    };
    auto span_distance = [&](Vec3 p) {
      return nearest_in(p, near >= 2 ? near - 2 : 0, std::min(span.size(), near + 9));
    };
    // Against input lines: on [f0, f1] the output lies within chord_deviation(f0, f1) of its
    // chord, and the distance to one input line is convex along the chord, so no point of
    // that piece is farther from the span than max(d_j(p0), d_j(p1)) + chord_deviation for any
    // input line j. Samples at the input vertices' places along the output, halfway between
    // them, and 1 mm apart; an interval whose bound exceeds the band is halved until it does
    // not.
    bool span_has_arcs = false;
    for (const Shape& piece : span) span_has_arcs = span_has_arcs || piece.arc;
    if (span_has_arcs) {
      // Against input arcs: sampled, with the 1-Lipschitz bound between samples.
      sweep(out, span_distance, tol, step, out_to_in, left_band);
    }
    std::vector<double> at{0.0, 1.0};
    if (!span_has_arcs) {
      for (const Shape& piece : span) at.push_back(out.fraction_of(piece.b));
    }
    std::sort(at.begin(), at.end());
    const std::size_t vertices = at.size();
    for (std::size_t q = 1; q < vertices; ++q) at.push_back((at[q - 1] + at[q]) / 2);
    std::sort(at.begin(), at.end());
    const double spacing = 1.0 / std::max(1.0, std::ceil(out.length));
    const double certified = tol + kCertifySlack;
    // Within [f0, f1] the input pieces near those nearest either end.
    auto bound = [&](double f0, double f1, std::size_t lo, std::size_t hi) {
      const Vec3 p0 = out.at(f0), p1 = out.at(f1);
      double best = 1e300;
      for (std::size_t j = lo; j < hi; ++j) best = std::min(best, std::max(span[j].distance_from(p0), span[j].distance_from(p1)));
      return best + out.chord_deviation(f0, f1);
    };
    long budget = 200000;  // halvings per span: past it the band counts as left (undecided)
    auto certify = [&](auto&& self, double f0, double d0, double f1, double d1, std::size_t lo, std::size_t hi,
                       int depth) -> void {
      if (d0 > certified || d1 > certified || depth > 40 || --budget < 0) {
        left_band = true;
        return;
      }
      if (bound(f0, f1, lo, hi) <= certified) return;
      const double fm = (f0 + f1) / 2;
      const double dm = nearest_in(out.at(fm), lo, hi);
      out_to_in = std::max(out_to_in, dm);
      self(self, f0, d0, fm, dm, lo, hi, depth + 1);
      self(self, fm, dm, f1, d1, lo, hi, depth + 1);
    };
    double previous = 0, d_previous = span_distance(out.a);
    std::size_t near_previous = near;
    out_to_in = std::max(out_to_in, d_previous);
    for (std::size_t q = 1; q < at.size() && !span_has_arcs; ++q) {
      if (at[q] <= previous) continue;
      for (double f = std::min(at[q], previous + spacing);; f = std::min(at[q], f + spacing)) {
        const double d = span_distance(out.at(f));
        const std::size_t near_here = near;
        out_to_in = std::max(out_to_in, d);
        const std::size_t lo = std::min(near_previous, near_here), hi = std::max(near_previous, near_here);
        if (!left_band) certify(certify, previous, d_previous, f, d, lo >= 2 ? lo - 2 : 0, std::min(span.size(), hi + 9), 0);
        near = near_here;
        previous = f;
        d_previous = d;
        near_previous = near_here;
        if (f >= at[q]) break;
      }
    }
  }
  if (left_band) problem("output " + where(o) + ": between samples the path may leave the band");
  const double e_err = std::abs(o.extrusion - e_in);
  report_.extrusion_error = std::max(report_.extrusion_error, e_err);
  if (e_err > options_.extrusion_tolerance + 1e-6 * std::abs(e_in)) {
    problem("output " + where(o) + ": extrudes " + std::to_string(o.extrusion) + " where the input extrudes " +
            std::to_string(e_in));
  }
  if (std::max(in_to_out, out_to_in) > report_.largest()) report_.worst_output_line = o.line;
  report_.input_to_output = std::max(report_.input_to_output, in_to_out);
  report_.output_to_input = std::max(report_.output_to_input, out_to_in);
  LayerDeviation& layer = layers_[std::llround(o.end.z * 100)];
  layer.z = std::round(o.end.z * 100) / 100;
  layer.input_to_output = std::max(layer.input_to_output, in_to_out);
  layer.output_to_input = std::max(layer.output_to_input, out_to_in);
  ++layer.output_motions;
  consume(span_end);
  return true;
}

void DeviationChecker::problem(const std::string& text) {
  if (report_.problems.size() < options_.max_problems) report_.problems.push_back(text);
  ++report_.problem_count;
}

std::string DeviationChecker::where(const PathPiece& p) {
  std::ostringstream s;
  s << "line " << p.line << " (" << p.end.x << ", " << p.end.y << ", " << p.end.z << ")";
  return s.str();
}

bool DeviationChecker::stop() {
  stopped_ = true;
  input_.clear();
  output_.clear();
  return true;
}

void DeviationChecker::consume(std::size_t pieces) {
  input_.erase(input_.begin(), input_.begin() + static_cast<std::ptrdiff_t>(pieces));
  output_.pop_front();
}

void DeviationChecker::input(const PathPiece& p) {
  if (stopped_ || finished_) return;
  ++report_.input_motions;
  input_.push_back(p);
  most_held_ = std::max(most_held_, input_.size() + output_.size());
  if (!output_.empty() && input_.size() >= retry_at_) drain(false);
}

void DeviationChecker::output(const PathPiece& p) {
  if (stopped_ || finished_) return;
  ++report_.output_motions;
  output_.push_back(p);
  most_held_ = std::max(most_held_, input_.size() + output_.size());
  drain(false);
}

void DeviationChecker::drain(bool final) {
  while (!stopped_ && !output_.empty()) {
    if (!check_next(final)) {
      // Waiting for input: look again when the input held has grown by half (a wrong output
      // would otherwise be looked up again for every input piece).
      retry_at_ = input_.size() + std::max<std::size_t>(1, input_.size() / 2);
      return;
    }
  }
  retry_at_ = 0;
}

DeviationReport DeviationChecker::finish() {
  if (finished_) return report_;
  drain(true);
  finished_ = true;
  if (report_.problem_count == 0) {
    std::size_t i = 0;
    while (i < input_.size() && is_point(input_[i]) && input_[i].extrusion == 0) ++i;
    if (i < input_.size()) problem("the output path ends before the input's (input " + where(input_[i]) + ")");
  }
  input_.clear();
  report_.layer_count = layers_.size();
  report_.worst_layers.clear();
  for (const auto& [key, layer] : layers_) report_.worst_layers.push_back(layer);
  auto worst = [](const LayerDeviation& l) { return std::max(l.input_to_output, l.output_to_input); };
  std::stable_sort(report_.worst_layers.begin(), report_.worst_layers.end(),
                   [&](const LayerDeviation& a, const LayerDeviation& b) { return worst(a) > worst(b); });
  if (report_.worst_layers.size() > 20) report_.worst_layers.resize(20);
  return report_;
}

DeviationReport check_deviation(const std::vector<PathPiece>& input, const std::vector<PathPiece>& output,
                                const DeviationOptions& options) {
  DeviationChecker checker(options);
  for (const PathPiece& p : input) checker.input(p);
  for (const PathPiece& p : output) checker.output(p);
  return checker.finish();
}

}  // namespace ncbridge::toolpath_optimizer
