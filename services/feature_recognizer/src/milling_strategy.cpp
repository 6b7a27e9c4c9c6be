#include "milling_strategy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <numbers>

namespace ncbridge::feature_recognizer {
namespace {

// sqrt(dx² + dy²): as exact as std::hypot for coordinates in millimetres, without its care for
// overflow, which costs more than the rest of these loops.
double planar_distance(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }

constexpr double kLevel = 1e-3;

struct Straight {
  Point2 a, b;
  double length() const { return planar_distance(b.x - a.x, b.y - a.y); }
};

// The cutting moves from where the path first reaches the layer's level (its entry ramps,
// plunges and helices left out) to its last move in XY: over a tab the run goes on.
std::vector<std::vector<Point2>> level_runs(const Layer& layer) {
  std::vector<std::vector<Point2>> runs;
  for (const auto& path : layer.paths) {
    std::size_t first = 0, last = 0;  // the first move at the level and the last in XY, 1-based
    for (std::size_t i = 1; i < path.size(); ++i) {
      if (first == 0 && std::abs(path[i].z - layer.z) < kLevel && std::abs(path[i - 1].z - layer.z) < kLevel) first = i;
      if (first != 0 && planar_distance(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y) > 1e-9) last = i;
    }
    if (first == 0) continue;
    std::vector<Point2> run;
    for (std::size_t i = first - 1; i <= last; ++i) run.push_back({path[i].x, path[i].y});
    runs.push_back(std::move(run));
  }
  return runs;
}

// A loop closes when the path comes back to a point it passed since the last loop closed,
// at least `min_length` of path later. The points passed are kept in cells of the closing
// distance, so each point looks at the few near it, not at the whole run.
int count_closed_loops(const std::vector<Point2>& run, double min_length,
                       std::vector<std::pair<std::size_t, std::size_t>>* ranges = nullptr) {
  constexpr double kClose = 1e-2;
  auto cell_of = [](Point2 p) {
    return std::pair{static_cast<long long>(std::floor(p.x / kClose)), static_cast<long long>(std::floor(p.y / kClose))};
  };
  auto key = [](long long x, long long y) { return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(y); };
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  // The points passed since the last loop closed, by cell: the latest in each cell, and before
  // each point the one it followed in its cell (linked lists in one array, no list per cell).
  // Entries before `loop_start` belong to loops already closed: they are passed over, not
  // erased (clearing the table at every loop cost its whole bucket array each time).
  std::unordered_map<std::uint64_t, std::size_t> latest;
  latest.reserve(run.size());
  std::vector<std::size_t> previous_in_cell(run.size(), kNone);
  std::size_t loop_start = 0;
  int loops = 0;
  std::vector<double> along(run.size(), 0);
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (i > 0) along[i] = along[i - 1] + planar_distance(run[i].x - run[i - 1].x, run[i].y - run[i - 1].y);
    const auto c = cell_of(run[i]);
    bool closes = false;
    std::size_t from = 0;
    for (long long dx = -1; dx <= 1 && !closes; ++dx) {
      for (long long dy = -1; dy <= 1 && !closes; ++dy) {
        auto it = latest.find(key(c.first + dx, c.second + dy));
        if (it == latest.end()) continue;
        for (std::size_t j = it->second; j != kNone && j >= loop_start; j = previous_in_cell[j]) {
          if (along[i] - along[j] > min_length && planar_distance(run[i].x - run[j].x, run[i].y - run[j].y) < kClose) {
            closes = true;
            from = j;
            break;
          }
        }
      }
    }
    if (closes) {
      ++loops;
      if (ranges) ranges->emplace_back(from, i);
      loop_start = i;  // the next loop starts here
    }
    auto [it, inserted] = latest.try_emplace(key(c.first, c.second), i);
    if (!inserted) {
      previous_in_cell[i] = it->second >= loop_start ? it->second : kNone;
      it->second = i;
    }
  }
  return loops;
}

// Whether `next` goes on in the direction of `s` along its line (within 0.01 mm of it).
bool continues(const Straight& s, const Straight& next) {
  const double len = s.length(), next_len = next.length();
  if (len < 1e-6 || next_len < 1e-6) return false;
  const double ux = (s.b.x - s.a.x) / len, uy = (s.b.y - s.a.y) / len;
  const double along = ((next.b.x - next.a.x) * ux + (next.b.y - next.a.y) * uy) / next_len;
  const double off = std::abs(-(next.b.x - s.a.x) * uy + (next.b.y - s.a.y) * ux);
  return along > 0 && off < 0.01;
}

// True when the moves lie on one straight line (within 0.05 mm), the longest move's.
bool on_one_line(const std::vector<Straight>& straights) {
  const Straight* longest = nullptr;
  for (const auto& s : straights) {
    if (!longest || s.length() > longest->length()) longest = &s;
  }
  if (!longest || longest->length() < 1e-3) return false;
  const double ux = (longest->b.x - longest->a.x) / longest->length(), uy = (longest->b.y - longest->a.y) / longest->length();
  auto off = [&](Point2 p) { return std::abs(-(p.x - longest->a.x) * uy + (p.y - longest->a.y) * ux); };
  return std::all_of(straights.begin(), straights.end(), [&](const Straight& s) { return off(s.a) < 0.05 && off(s.b) < 0.05; });
}

// Kåsa's algebraic circle fit (x² + y² + Dx + Ey + F = 0, least squares) of the path vertices
// within 0.05 mm of the circle about `guess` with `radius`; `guess` when they are too few.
Point2 fit_circle_center(const Layer& layer, Point2 guess, double radius) {
  double s[3][3] = {}, t[3] = {};
  int n = 0;
  for (const auto& path : layer.paths) {
    for (const auto& p : path) {
      if (std::abs(planar_distance(p.x - guess.x, p.y - guess.y) - radius) > 0.05) continue;
      const double x = p.x - guess.x, y = p.y - guess.y, row[3] = {x, y, 1}, rhs = -(x * x + y * y);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) s[i][j] += row[i] * row[j];
        t[i] += row[i] * rhs;
      }
      ++n;
    }
  }
  if (n < 3) return guess;
  // Cramer's rule on the 3 x 3 normal equations.
  auto det = [](double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(s);
  if (std::abs(d) < 1e-12) return guess;
  double solution[2];
  for (int k = 0; k < 2; ++k) {
    double m[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] = j == k ? t[i] : s[i][j];
    }
    solution[k] = det(m) / d;
  }
  return {guess.x - solution[0] / 2, guess.y - solution[1] / 2};
}

// The distances of the path vertices from a centre, sorted with their running sums: the mean
// distance of the vertices near any circle about that centre in O(log n).
class RadialSums {
 public:
  RadialSums(const Layer& layer, Point2 c) {
    for (const auto& path : layer.paths) {
      for (const auto& p : path) distances_.push_back(planar_distance(p.x - c.x, p.y - c.y));
    }
    std::sort(distances_.begin(), distances_.end());
    sums_.resize(distances_.size() + 1, 0);
    for (std::size_t i = 0; i < distances_.size(); ++i) sums_[i + 1] = sums_[i] + distances_[i];
  }
  // The mean distance of the vertices within `band` of `radius` (strictly), `radius` when none.
  double mean_near(double radius, double band) const {
    const auto lo = std::upper_bound(distances_.begin(), distances_.end(), radius - band);
    const auto hi = std::lower_bound(distances_.begin(), distances_.end(), radius + band);
    if (hi <= lo) return radius;
    const auto a = static_cast<std::size_t>(lo - distances_.begin()), b = static_cast<std::size_t>(hi - distances_.begin());
    return (sums_[b] - sums_[a]) / static_cast<double>(b - a);
  }

 private:
  std::vector<double> distances_, sums_;
};

// Whether the layer's moves go round one centre (the centre of their extent), at one or more
// radii, each a full turn or more, with at most 10 % of the length elsewhere (links, the move
// back to the centre). A chord counts as on the circle when its middle is within the sagitta
// a chorded arc can have.
bool find_circles(const Layer& layer, StrategyAnalysis& out) {
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  for (const auto& path : layer.paths) {
    for (const auto& p : path) {
      xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
  }
  if (xmax <= xmin || ymax <= ymin) return false;
  const Point2 c{(xmin + xmax) / 2, (ymin + ymax) / 2};
  struct Ring {
    double radius, sweep;
  };
  std::vector<Ring> rings;
  std::multimap<double, std::size_t> by_radius;  // ring radius -> index in `rings`
  double total = 0, on = 0, descent = 0, flat = 0;
  for (const auto& path : layer.paths) {
    for (std::size_t i = 1; i < path.size(); ++i) {
      const auto& a = path[i - 1];
      const auto& b = path[i];
      const double length = planar_distance(b.x - a.x, b.y - a.y);
      if (length < 1e-9) continue;
      const double r0 = planar_distance(a.x - c.x, a.y - c.y), r1 = planar_distance(b.x - c.x, b.y - c.y);
      if (std::abs(std::abs(r1 - r0) - length) < 1e-3 * length) continue;  // a radial link between circles
      total += length;
      const double rm = planar_distance((a.x + b.x) / 2 - c.x, (a.y + b.y) / 2 - c.y);
      const double tol = std::max(0.02, 0.002 * r0);
      if (r0 < 0.05 || std::abs(r0 - r1) > tol || r0 - rm > std::max(0.05, 0.005 * r0)) continue;
      on += length;
      descent += std::max(0.0, a.z - b.z);
      if (std::abs(a.z - b.z) < 1e-6) flat += length;
      double turn = std::atan2(b.y - c.y, b.x - c.x) - std::atan2(a.y - c.y, a.x - c.x);
      while (turn > std::numbers::pi) turn -= 2 * std::numbers::pi;
      while (turn < -std::numbers::pi) turn += 2 * std::numbers::pi;
      const double r = (r0 + r1) / 2;
      // The first ring made (in path order) within the tolerance of r: looked up by radius.
      std::size_t found = rings.size();
      for (auto it = by_radius.lower_bound(r - tol); it != by_radius.end() && it->first <= r + tol; ++it) {
        if (std::abs(it->first - r) < tol) found = std::min(found, it->second);
      }
      if (found == rings.size()) {
        rings.push_back({r, turn});
        by_radius.emplace(r, found);
      } else {
        rings[found].sweep += turn;
      }
    }
  }
  if (rings.empty() || on < 0.9 * total) return false;
  for (const auto& ring : rings) {
    if (std::abs(ring.sweep) < 2 * std::numbers::pi - 0.01) return false;
  }
  std::sort(rings.begin(), rings.end(), [](const Ring& a, const Ring& b) { return a.radius < b.radius; });
  // The extent's centre is off by up to a chord's sagitta: the circle through the outermost
  // ring's vertices (which lie on the true circle) by least squares.
  const auto fitted = fit_circle_center(layer, c, rings.back().radius);
  const RadialSums sums(layer, fitted);
  for (const auto& ring : rings) out.circle_radii.push_back(sums.mean_near(ring.radius, 0.05));
  out.circle_center = fitted;
  out.circle_radius = out.circle_radii.back();
  out.single_circle = rings.size() == 1;
  out.helical = descent > 1e-3;
  // A helix down to the level, then flat circles at more radii than one: the helix was the
  // entry, the circles at the level clear it (contour parallel about one centre).
  out.helical_entry = out.helical && rings.size() > 1 && flat > on - flat;
  return true;
}

// The long straight moves (at least `min_pass`) along one direction (±1°): how many go each
// way, and how their offsets across that direction step from one to the next. Parallel passes
// that sweep an area progress one way (≥ 75 % of the steps); nested contours have long
// parallel sides too, but their offsets jump from side to side.
struct Passes {
  int forward = 0, backward = 0, rising = 0, falling = 0;
  std::vector<double> gaps;
  int count() const { return forward + backward; }
  bool progress() const { return std::max(rising, falling) >= 0.75 * (rising + falling); }
  // Bidirectional when both senses occur (≥ ¼), else unidirectional.
  Strategy strategy() const {
    return std::min(forward, backward) >= std::max(1, count() / 4) ? Strategy::Bidirectional : Strategy::Unidirectional;
  }
  double stepover() const {  // the median offset step
    if (gaps.empty()) return 0;
    auto g = gaps;
    std::nth_element(g.begin(), g.begin() + static_cast<std::ptrdiff_t>(g.size() / 2), g.end());
    return g[g.size() / 2];
  }
};

// The passes along the direction of the most length (1° bins, direction modulo 180°), when
// that is more than `min_share` of `total`; with `any_direction`, along the first direction by
// length (each over `min_share`) whose three or more passes progress (a zigzag whose links
// along the walls are as long as its passes).
std::optional<Passes> parallel_passes(const std::vector<Straight>& straights, double total, double min_pass,
                                      double min_share, bool any_direction) {
  std::map<int, double> bins;
  for (const auto& s : straights) {
    if (s.length() < min_pass) continue;
    double deg = std::atan2(s.b.y - s.a.y, s.b.x - s.a.x) * 180 / std::numbers::pi;
    if (deg < 0) deg += 180;
    bins[static_cast<int>(std::lround(deg)) % 180] += s.length();
  }
  std::vector<std::pair<double, int>> directions;  // (length about it, degrees)
  for (const auto& [deg, len] : bins) {
    const double around = len + (bins.count((deg + 1) % 180) ? bins[(deg + 1) % 180] : 0) +
                          (bins.count((deg + 179) % 180) ? bins[(deg + 179) % 180] : 0);
    directions.emplace_back(around, deg);
  }
  // Longest first; among equal lengths the lowest angle (the order the bins were met in).
  std::stable_sort(directions.begin(), directions.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [length, dominant] : directions) {
    if (length <= min_share * total) break;
    const double ux = std::cos(dominant * std::numbers::pi / 180), uy = std::sin(dominant * std::numbers::pi / 180);
    Passes p;
    std::vector<double> sequence;
    for (const auto& s : straights) {
      const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
      const double along = (dx * ux + dy * uy) / s.length();
      if (std::abs(along) < std::cos(1.5 * std::numbers::pi / 180) || s.length() < min_pass) continue;
      (along > 0 ? p.forward : p.backward)++;
      sequence.push_back(-s.a.x * uy + s.a.y * ux);
    }
    for (std::size_t i = 1; i < sequence.size(); ++i) {
      const double d = sequence[i] - sequence[i - 1];
      if (std::abs(d) <= 0.05) continue;
      (d > 0 ? p.rising : p.falling)++;
      p.gaps.push_back(std::abs(d));
    }
    if (!any_direction || (p.count() >= 3 && p.progress() && !p.gaps.empty())) return p;
  }
  return std::nullopt;
}

// A zigzag whose passes are not taken in order (FreeCAD's: the outer two, then the middle):
// at least three long moves along one direction, each at its own offset, all between the same
// two lines across them (the area's ends), in alternating senses. Nested contours have as many
// parallel moves, but each loop's are shorter than the one around it.
struct Sweep {
  Strategy strategy = Strategy::None;
  double stepover = 0;
};

std::optional<Sweep> unordered_zigzag(const std::vector<Straight>& straights, double min_pass) {
  std::map<int, std::vector<const Straight*>> by_direction;
  for (const auto& s : straights) {
    if (s.length() < min_pass) continue;
    double deg = std::atan2(s.b.y - s.a.y, s.b.x - s.a.x) * 180 / std::numbers::pi;
    if (deg < 0) deg += 180;
    by_direction[static_cast<int>(std::lround(deg)) % 180].push_back(&s);
  }
  for (const auto& [deg, passes] : by_direction) {
    if (passes.size() < 3) continue;
    const double ux = std::cos(deg * std::numbers::pi / 180), uy = std::sin(deg * std::numbers::pi / 180);
    auto along = [&](Point2 p) { return p.x * ux + p.y * uy; };
    auto across = [&](Point2 p) { return -p.x * uy + p.y * ux; };
    const double lo = std::min(along(passes.front()->a), along(passes.front()->b));
    const double hi = std::max(along(passes.front()->a), along(passes.front()->b));
    std::vector<double> offsets;
    bool same_span = true, alternating = true;
    for (std::size_t k = 0; k < passes.size() && same_span; ++k) {
      const auto* p = passes[k];
      same_span = std::abs(std::min(along(p->a), along(p->b)) - lo) < 0.05 && std::abs(std::max(along(p->a), along(p->b)) - hi) < 0.05 &&
                  std::abs(across(p->a) - across(p->b)) < 0.05;
      if (k > 0) alternating = alternating && (along(p->b) - along(p->a) > 0) != (along(passes[k - 1]->b) - along(passes[k - 1]->a) > 0);
      offsets.push_back(across(p->a));
    }
    if (!same_span || !alternating) continue;
    std::sort(offsets.begin(), offsets.end());
    std::vector<double> gaps;
    for (std::size_t k = 1; k < offsets.size(); ++k) gaps.push_back(offsets[k] - offsets[k - 1]);
    if (*std::min_element(gaps.begin(), gaps.end()) <= 0.05) continue;  // two passes on one line
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
    return Sweep{Strategy::Bidirectional, gaps[gaps.size() / 2]};
  }
  return std::nullopt;
}

std::vector<Straight> straights_of(const std::vector<Point2>& run, std::size_t first, std::size_t last, double& total) {
  std::vector<Straight> out;
  for (std::size_t i = first + 1; i <= last && i < run.size(); ++i) {
    Straight s{run[i - 1], run[i]};
    total += s.length();
    if (s.length() > 1e-6) out.push_back(s);
  }
  return out;
}

// FreeCAD's ZigZagOffset and its kin: a closed loop along the boundary (the offset contour) that
// ends the level's path or begins it, and parallel passes sweeping the inside in the rest:
// bidirectional-contour when the loop comes last, contour-bidirectional when first.
std::optional<Sweep> zigzag_and_contour(const std::vector<std::vector<Point2>>& runs, double tool_r) {
  if (runs.size() != 1 || runs.front().size() < 4) return std::nullopt;
  const auto& run = runs.front();
  const double min_loop = 2 * std::max(tool_r, 0.5);
  std::vector<double> along(run.size(), 0);
  for (std::size_t i = 1; i < run.size(); ++i) {
    along[i] = along[i - 1] + planar_distance(run[i].x - run[i - 1].x, run[i].y - run[i - 1].y);
  }
  auto near = [&](std::size_t a, std::size_t b) { return planar_distance(run[a].x - run[b].x, run[a].y - run[b].y) < 1e-2; };
  auto sweeps = [&](std::size_t first, std::size_t last) -> std::optional<double> {
    double total = 0;
    const auto rest = straights_of(run, first, last, total);
    const auto passes = parallel_passes(rest, total, tool_r, 0.3, true);
    if (!passes || passes->strategy() != Strategy::Bidirectional) return std::nullopt;
    return passes->stepover();
  };
  const std::size_t end = run.size() - 1;
  // The loop that ends the path: from the first point the path's end comes back to.
  for (std::size_t j = 0; j < end; ++j) {
    if (along[end] - along[j] < min_loop) break;
    if (!near(j, end)) continue;
    if (const auto stepover = sweeps(0, j)) return Sweep{Strategy::BidirectionalContour, *stepover};
    break;
  }
  // The loop that begins it: to the first point that comes back to its start.
  for (std::size_t i = 1; i <= end; ++i) {
    if (along[i] < min_loop || !near(0, i)) continue;
    if (const auto stepover = sweeps(i, end)) return Sweep{Strategy::ContourBidirectional, *stepover};
    break;
  }
  return std::nullopt;
}

}  // namespace

StrategyAnalysis analyse_strategy(const Layer& layer) {
  StrategyAnalysis out;
  const double tool_r = layer.tool.diameter / 2;

  const auto runs = level_runs(layer);

  // Circles or helices about one centre: a hole milled by interpolation, or a circular pocket.
  if (find_circles(layer, out)) {
    if (out.helical || out.single_circle) {
      out.strategy = out.helical ? Strategy::Helical : Strategy::Contour;
    }
    if (out.helical_entry || (!out.helical && !out.single_circle)) {
      out.strategy = Strategy::ContourParallel;
    }
    out.closed_loops = static_cast<int>(out.circle_radii.size());
    return out;
  }

  std::vector<Straight> straights;
  double total = 0;
  for (const auto& run : runs) {
    for (std::size_t i = 1; i < run.size(); ++i) {
      Straight s{run[i - 1], run[i]};
      total += s.length();
      if (s.length() <= 1e-6) continue;
      // A move that goes on along the line of the one before (a vertex where a loop was
      // entered, a pass split by a tab) is one pass with it.
      if (!straights.empty() && straights.back().b.x == s.a.x && straights.back().b.y == s.a.y && continues(straights.back(), s)) {
        straights.back().b = s.b;
      } else {
        straights.push_back(s);
      }
    }
  }
  if (total <= 0) {
    out.strategy = Strategy::Plunge;
    return out;
  }
  // Loops whose box is under two tool diameters each way are a trochoid's (adaptive clearing
  // cuts in small loops); the loops of contours run along the area's boundary.
  int large_loops = 0;
  for (const auto& run : runs) {
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    out.closed_loops += count_closed_loops(run, 2 * std::max(tool_r, 0.5), &ranges);
    for (const auto& [from, to] : ranges) {
      double x0 = run[from].x, x1 = x0, y0 = run[from].y, y1 = y0;
      for (std::size_t i = from; i <= to; ++i) {
        x0 = std::min(x0, run[i].x), x1 = std::max(x1, run[i].x);
        y0 = std::min(y0, run[i].y), y1 = std::max(y1, run[i].y);
      }
      if (std::max(x1 - x0, y1 - y0) >= 4 * tool_r) ++large_loops;
    }
  }

  // Every move on one straight line (once, or back and forth): a slot along its centre line.
  if (on_one_line(straights)) {
    out.strategy = Strategy::CenterMilling;
    return out;
  }

  // Parallel passes along the direction of the most length, if that is more than 60 % of it.
  if (const auto passes = parallel_passes(straights, total, tool_r, 0.6, false)) {
    if (passes->count() == 1 && out.closed_loops == 0) {
      out.strategy = Strategy::CenterMilling;  // one straight pass: a slot along its centre line
      return out;
    }
    // Two passes side by side (joined by a rapid, as a face milled in two passes) sweep too.
    // Passes close no loop but a finishing contour: two or more large loops are nested
    // contours, whose parallel sides can step one way too.
    const bool enough = passes->count() >= 3 || (passes->count() == 2 && out.closed_loops == 0);
    if (enough && passes->progress() && large_loops < 2) {
      out.stepover = passes->stepover();
      out.strategy = passes->strategy();
      return out;
    }
  }
  // A zigzag and one contour along the boundary, in either order.
  if (const auto both = zigzag_and_contour(runs, tool_r)) {
    out.strategy = both->strategy;
    out.stepover = both->stepover;
    return out;
  }
  // A zigzag over a rectangle whose passes are not taken in order.
  if (const auto zigzag = unordered_zigzag(straights, tool_r)) {
    out.strategy = zigzag->strategy;
    out.stepover = zigzag->stepover;
    return out;
  }

  // Many separate passes at one level that close no loop along a boundary (small trochoid loops
  // do not count): adaptive clearing.
  if (layer.paths.size() >= 4 && large_loops <= 1) {
    out.strategy = Strategy::Adaptive;
    return out;
  }
  if (out.closed_loops >= 2) {
    out.strategy = Strategy::ContourParallel;
  } else if (out.closed_loops == 1) {
    out.strategy = Strategy::Contour;
  } else {
    // An open path that neither closes nor runs parallel: a centre line when it sweeps one
    // tool width along its whole length (it never overlaps itself), else a spiral.
    double length = 0;
    for (const auto& run : runs) {
      for (std::size_t i = 1; i < run.size(); ++i) length += planar_distance(run[i].x - run[i - 1].x, run[i].y - run[i - 1].y);
    }
    const double one_width = length * 2 * tool_r + std::numbers::pi * tool_r * tool_r;
    const double swept = layer.area.area();
    const bool center_line = swept <= 1.05 * one_width && swept >= 0.9 * one_width;
    out.strategy = center_line ? Strategy::CenterMilling : Strategy::ContourSpiral;
  }
  return out;
}

}  // namespace ncbridge::feature_recognizer
