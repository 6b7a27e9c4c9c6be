#include "cutting_layers.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "box_index.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::feature_recognizer {
namespace {

// sqrt(dx² + dy²): as exact as std::hypot for coordinates in millimetres, without its care for
// overflow, which costs more than the rest of these loops.
double planar_distance(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }

constexpr double kLevelTolerance = 1e-3;  // mm: two z values closer than this are one level

bool finite(const Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

void append_arc(const Point3& from, const Move& move, double tolerance, CuttingPass& pass) {
  const double r0 = planar_distance(from.x - move.center_x, from.y - move.center_y);
  const double r1 = planar_distance(move.end.x - move.center_x, move.end.y - move.center_y);
  const double a0 = std::atan2(from.y - move.center_y, from.x - move.center_x);
  const double a1 = std::atan2(move.end.y - move.center_y, move.end.x - move.center_x);
  const double two_pi = 2 * std::numbers::pi;
  double sweep = move.clockwise ? a0 - a1 : a1 - a0;
  while (sweep <= 1e-9) sweep += two_pi;
  sweep += two_pi * std::max(0, move.turns - 1);
  if (move.clockwise) sweep = -sweep;
  const double r = std::max(r0, r1);
  const double max_step = r > tolerance ? 2 * std::acos(1 - tolerance / r) : std::numbers::pi / 4;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / max_step)));
  for (int i = 1; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    const double a = a0 + sweep * t, rr = r0 + (r1 - r0) * t;
    pass.points.push_back({move.center_x + rr * std::cos(a), move.center_y + rr * std::sin(a),
                           from.z + (move.end.z - from.z) * t});
  }
  pass.points.back() = move.end;
  pass.xy_length += std::abs(sweep) * (r0 + r1) / 2;
}

// A pass ends at a rapid or a tool change; it runs on across workingsteps otherwise (an
// upstream segmenter may split a plunge from the cut it starts, at a feed change). Each pass is
// handed on as it ends, so that only one is held at a time.
template <typename OnPass>
void cut_into_passes(const std::vector<ToolpathWorkingstep>& workingsteps, double tolerance, OnPass on_pass) {
  CuttingPass current;
  std::size_t sequence = 0;
  auto flush = [&] {
    if (current.points.size() >= 2) {
      current.sequence = sequence++;
      current.z_min = current.z_max = current.points.front().z;
      for (const auto& p : current.points) {
        current.z_min = std::min(current.z_min, p.z);
        current.z_max = std::max(current.z_max, p.z);
      }
      on_pass(std::move(current));
    }
    current = CuttingPass{};
  };
  Point3 at;
  for (std::size_t w = 0; w < workingsteps.size(); ++w) {
    const auto& ws = workingsteps[w];
    const bool continues = w > 0 && workingsteps[w - 1].tool.number == ws.tool.number && ws.start == at &&
                           !ws.cycle && !workingsteps[w - 1].cycle;
    if (!continues) flush();
    at = ws.start;
    for (const auto& move : ws.moves) {
      if (!finite(move.end) || !std::isfinite(move.center_x) || !std::isfinite(move.center_y)) {
        throw InputError({"", move.source_line, 1}, "workingstep " + std::to_string(w) +
                                                        ": a move has a coordinate that is not a finite number");
      }
      if (move.kind == MoveKind::Rapid) {
        flush();
        at = move.end;
        continue;
      }
      if (current.points.empty()) {
        current.workingstep = w;
        current.points.push_back(at);
      }
      if (current.workingstep_runs.empty() || current.workingstep_runs.back().second != w) {
        // The points this move adds (and the pass's first point) belong to workingstep w.
        current.workingstep_runs.emplace_back(current.workingstep_runs.empty() ? 0 : current.points.size(), w);
      }
      if (move.kind == MoveKind::Arc) {
        append_arc(at, move, tolerance, current);
      } else {
        current.xy_length += planar_distance(move.end.x - at.x, move.end.y - at.y);
        current.points.push_back(move.end);
      }
      at = move.end;
    }
  }
  flush();
}

// A pass whose z goes up and down many times while x and y move is surface machining.
bool is_freeform(const CuttingPass& pass) {
  double sloped = 0, total = 0;
  int reversals = 0, last_sign = 0;
  for (std::size_t i = 1; i < pass.points.size(); ++i) {
    const auto& a = pass.points[i - 1];
    const auto& b = pass.points[i];
    const double xy = planar_distance(b.x - a.x, b.y - a.y), dz = b.z - a.z;
    total += xy;
    if (xy > 1e-6 && std::abs(dz) > 1e-4) sloped += xy;
    if (std::abs(dz) > 1e-4) {
      const int sign = dz > 0 ? 1 : -1;
      if (last_sign != 0 && sign != last_sign && xy > 1e-6) ++reversals;
      last_sign = sign;
    }
  }
  return total > 0 && sloped > 0.5 * total && reversals >= 4;
}

Layer make_layer(const CuttingPass& pass, const ToolpathWorkingstep& ws, std::vector<Point3> path,
                 std::size_t first_point) {
  Layer layer;
  // The workingsteps of the points after the first (the first is where the cut starts from).
  layer.workingsteps = pass.workingsteps_of(first_point + 1, std::min(first_point + path.size(), pass.points.size()));
  if (layer.workingsteps.empty()) layer.workingsteps = {pass.workingstep};
  layer.sequence = pass.sequence;
  layer.tool = ws.tool;
  layer.feed = ws.feed;
  layer.spindle_rpm = ws.spindle_rpm;
  layer.z = layer.z_top = path.front().z;
  for (const auto& p : path) {
    layer.z = std::min(layer.z, p.z);
    layer.z_top = std::max(layer.z_top, p.z);
  }
  layer.paths.push_back(std::move(path));
  return layer;
}

double xy_length(const Layer& layer) {
  double length = 0;
  for (const auto& path : layer.paths) {
    for (std::size_t i = 1; i < path.size(); ++i) length += planar_distance(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
  }
  return length;
}

// A short run above the level the pass cuts at, then back down to it (or the end of the pass):
// the tool lifting over a tab or a clamp, part of the lower level.
std::vector<Layer> merge_tabs(std::vector<Layer> slices) {
  if (slices.empty()) return slices;
  std::vector<double> lengths;
  lengths.reserve(slices.size());
  for (const auto& slice : slices) lengths.push_back(xy_length(slice));
  std::vector<Layer> out;
  out.reserve(slices.size());
  out.push_back(std::move(slices.front()));
  double low_length = lengths.front();
  for (std::size_t k = 1; k < slices.size();) {
    auto& low = out.back();
    const bool rises = slices[k].z > low.z + kLevelTolerance;
    const bool back = k + 1 == slices.size() || std::abs(slices[k + 1].z - low.z) < kLevelTolerance;
    if (!rises || !back || lengths[k] >= low_length) {
      out.push_back(std::move(slices[k]));
      low_length = lengths[k];
      ++k;
      continue;
    }
    const std::size_t last = std::min(k + 1, slices.size() - 1);
    for (std::size_t j = k; j <= last; ++j) {
      auto& path = low.paths.back();
      path.insert(path.end(), slices[j].paths.front().begin() + 1, slices[j].paths.front().end());
      for (auto w : slices[j].workingsteps) {
        if (low.workingsteps.back() < w) low.workingsteps.push_back(w);
      }
      low.z_top = std::max(low.z_top, slices[j].z_top);
      low_length += lengths[j];  // the slice's moves, now the level's (its first point was the level's last)
    }
    k = last + 1;
  }
  return out;
}

// Slices a milling pass at its cutting levels: each run of horizontal moves is a level; the
// moves that descend to it (plunge, ramp, helix) belong to it; moves after the last level
// (a feed retract) belong to the last level.
std::vector<Layer> slice_pass(const CuttingPass& pass, const ToolpathWorkingstep& ws) {
  std::vector<Layer> out;
  if (is_freeform(pass)) {
    Layer layer = make_layer(pass, ws, pass.points, 0);
    layer.freeform = true;
    out.push_back(std::move(layer));
    return out;
  }
  std::vector<Point3> piece{pass.points.front()};
  std::size_t piece_first = 0;
  bool piece_has_level = false;
  double piece_level = 0;
  for (std::size_t i = 1; i < pass.points.size(); ++i) {
    const auto& a = pass.points[i - 1];
    const auto& b = pass.points[i];
    const bool horizontal = std::abs(b.z - a.z) < kLevelTolerance && planar_distance(b.x - a.x, b.y - a.y) > 0;
    if (horizontal) {
      if (piece_has_level && std::abs(a.z - piece_level) > kLevelTolerance) {
        // A new level begins: close the current piece at its last point on the old level.
        out.push_back(make_layer(pass, ws, piece, piece_first));
        piece = {a};
        piece_first = i - 1;
      }
      piece_has_level = true;
      piece_level = a.z;
    } else if (piece_has_level && b.z < piece_level - kLevelTolerance) {
      // Descending below the current level: this starts the next level's entry.
      out.push_back(make_layer(pass, ws, piece, piece_first));
      piece = {a};
      piece_first = i - 1;
      piece_has_level = false;
    }
    piece.push_back(b);
  }
  if (piece.size() >= 2) {
    if (!piece_has_level && !out.empty() && piece.back().z >= out.back().z - kLevelTolerance) {
      auto& last = out.back().paths.back();
      last.insert(last.end(), piece.begin() + 1, piece.end());
      for (auto w : pass.workingsteps_of(piece_first + 1, pass.points.size())) {
        if (out.back().workingsteps.back() < w) out.back().workingsteps.push_back(w);
      }
      out.back().z_top = std::max(out.back().z_top, piece.back().z);
    } else {
      out.push_back(make_layer(pass, ws, piece, piece_first));
    }
  }
  return merge_tabs(std::move(out));
}

bool boxes_touch(const Box2& a, const Box2& b) {
  return a.xmin <= b.xmax && b.xmin <= a.xmax && a.ymin <= b.ymax && b.ymin <= a.ymax;
}

Box2 path_box(const std::vector<std::vector<Point3>>& paths, double grow) {
  Box2 box{1e300, 1e300, -1e300, -1e300};
  for (const auto& path : paths) {
    for (const auto& p : path) {
      box.xmin = std::min(box.xmin, p.x - grow);
      box.ymin = std::min(box.ymin, p.y - grow);
      box.xmax = std::max(box.xmax, p.x + grow);
      box.ymax = std::max(box.ymax, p.y + grow);
    }
  }
  return box;
}

}  // namespace

bool CuttingPass::z_only() const {
  for (const auto& p : points) {
    if (planar_distance(p.x - points.front().x, p.y - points.front().y) > 1e-3) return false;
  }
  return true;
}

std::vector<std::size_t> CuttingPass::workingsteps_of(std::size_t first, std::size_t last) const {
  std::vector<std::size_t> out;
  for (std::size_t r = 0; r < workingstep_runs.size(); ++r) {
    const std::size_t begin = workingstep_runs[r].first;
    const std::size_t end = r + 1 < workingstep_runs.size() ? workingstep_runs[r + 1].first : points.size();
    if (begin < last && first < end && (out.empty() || out.back() != workingstep_runs[r].second)) {
      out.push_back(workingstep_runs[r].second);
    }
  }
  return out;
}

std::vector<std::vector<Point2>> Layer::xy_paths() const {
  std::vector<std::vector<Point2>> out;
  for (const auto& path : paths) {
    std::vector<Point2> line;
    line.reserve(path.size());
    for (const auto& p : path) line.push_back({p.x, p.y});
    out.push_back(std::move(line));
  }
  return out;
}

bool is_hole_making_tool(setup::ToolType type) {
  using T = setup::ToolType;
  return type == T::Drill || type == T::CenterDrill || type == T::SpotDrill || type == T::Reamer ||
         type == T::Tap || type == T::BoringBar;
}

CutterLocationAnalysis analyse_cutter_locations(const std::vector<ToolpathWorkingstep>& workingsteps,
                                                double chord_tolerance, const std::function<void()>& checkpoint) {
  CutterLocationAnalysis out;
  // Layers as they are made; a layer merged into a later one leaves a dead slot (kept so that the
  // run's index stays valid), removed at the end.
  std::vector<Layer> layers;
  std::vector<char> dead;
  std::size_t run_begin = 0;  // the first layer of the current run of one tool at one level
  BoxIndex run_index(25.0);   // the run's layers by their extents
  cut_into_passes(workingsteps, chord_tolerance, [&](CuttingPass&& pass) {
    if (checkpoint) checkpoint();
    const auto& ws = workingsteps[pass.workingstep];
    if (pass.z_only() || (is_hole_making_tool(ws.tool.type) && ws.cycle)) {
      if (pass.z_min >= pass.points.front().z - kLevelTolerance) {
        return;  // a feed retract out of a hole cuts nothing new
      }
      DrillPass d;
      d.workingstep = pass.workingstep;
      d.sequence = pass.sequence;
      d.tool = ws.tool;
      d.at = {pass.points.front().x, pass.points.front().y};
      d.z_bottom = pass.z_min;
      d.z_top = pass.z_max;
      d.cycle = ws.cycle;
      d.feed = ws.feed;
      d.spindle_rpm = ws.spindle_rpm;
      if (ws.cycle) d.at = {ws.cycle->x, ws.cycle->y};
      out.drill_passes.push_back(std::move(d));
      return;
    }
    if (ws.tool.diameter <= 0) {
      const std::uint32_t line = ws.moves.empty() ? 0 : ws.moves.front().source_line;
      throw InputError({"", line, 1}, "workingstep " + std::to_string(pass.workingstep) + ": tool T" +
                                       std::to_string(ws.tool.number) +
                                       " has no diameter, so its cutting area is unknown");
    }
    for (auto& layer : slice_pass(pass, ws)) {
      const double r = ws.tool.diameter / 2;
      layer.extent = path_box(layer.paths, r);
      // Pieces of one tool at one level, one after the other, touching (also through others of
      // the run, as passes broken around an island are): one layer.
      const bool continues_run = run_begin < layers.size() && !layer.freeform && !layers.back().freeform &&
                                 layers.back().tool.number == layer.tool.number &&
                                 std::abs(layers.back().z - layer.z) < kLevelTolerance;
      if (!continues_run) {
        run_begin = layers.size();
        run_index = BoxIndex(25.0);
      }
      layers.push_back(std::move(layer));
      dead.push_back(0);
      run_index.insert(layers.size() - 1, layers.back().extent);
      for (bool merged = true; merged;) {
        merged = false;
        const std::size_t at = layers.size() - 1;
        auto& last = layers[at];
        for (auto k : run_index.candidates(last.extent)) {
          if (k < run_begin || k >= at || dead[k] || !boxes_touch(layers[k].extent, last.extent)) continue;
          auto& into = layers[k];
          for (auto& p : last.paths) into.paths.push_back(std::move(p));
          // Sorted and made unique once, at the end.
          into.workingsteps.insert(into.workingsteps.end(), last.workingsteps.begin(), last.workingsteps.end());
          into.z_top = std::max(into.z_top, last.z_top);
          into.extent = {std::min(into.extent.xmin, last.extent.xmin), std::min(into.extent.ymin, last.extent.ymin),
                         std::max(into.extent.xmax, last.extent.xmax), std::max(into.extent.ymax, last.extent.ymax)};
          // The merged layer goes last, so that it can absorb the others it now touches.
          layers[at] = std::move(into);
          dead[k] = 1;
          run_index.insert(at, layers[at].extent);
          merged = true;
          break;
        }
      }
    }
  });
  for (std::size_t i = 0; i < layers.size(); ++i) {
    if (dead[i]) continue;
    auto& w = layers[i].workingsteps;
    std::sort(w.begin(), w.end());
    w.erase(std::unique(w.begin(), w.end()), w.end());
    out.layers.push_back(std::move(layers[i]));
  }
  return out;
}

}  // namespace ncbridge::feature_recognizer
