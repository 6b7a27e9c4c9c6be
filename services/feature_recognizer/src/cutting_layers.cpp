#include "cutting_layers.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ncbridge/common/error.hpp"

namespace ncbridge::feature_recognizer {
namespace {

constexpr double kLevelTolerance = 1e-3;  // mm: two z values closer than this are one level

bool finite(const Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

void append_arc(const Point3& from, const Move& move, double tolerance, CuttingPass& pass) {
  const double r0 = std::hypot(from.x - move.center_x, from.y - move.center_y);
  const double r1 = std::hypot(move.end.x - move.center_x, move.end.y - move.center_y);
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
  pass.arcs.push_back({{move.center_x, move.center_y}, (r0 + r1) / 2, sweep, from.z, move.end.z});
  pass.xy_length += std::abs(sweep) * (r0 + r1) / 2;
}

// A pass ends at a rapid or a tool change; it runs on across workingsteps otherwise (an
// upstream segmenter may split a plunge from the cut it starts, at a feed change).
std::vector<CuttingPass> cut_into_passes(const std::vector<ToolpathWorkingstep>& workingsteps, double tolerance) {
  std::vector<CuttingPass> passes;
  CuttingPass current;
  auto flush = [&] {
    if (current.points.size() >= 2) passes.push_back(std::move(current));
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
        current.point_workingsteps.push_back(w);
      }
      if (move.kind == MoveKind::Arc) {
        append_arc(at, move, tolerance, current);
      } else {
        current.xy_length += std::hypot(move.end.x - at.x, move.end.y - at.y);
        current.points.push_back(move.end);
      }
      current.point_workingsteps.resize(current.points.size(), w);
      at = move.end;
    }
  }
  flush();
  for (std::size_t i = 0; i < passes.size(); ++i) passes[i].sequence = i;
  for (auto& pass : passes) {
    pass.z_min = pass.z_max = pass.points.front().z;
    for (const auto& p : pass.points) {
      pass.z_min = std::min(pass.z_min, p.z);
      pass.z_max = std::max(pass.z_max, p.z);
    }
  }
  return passes;
}

// A pass whose z goes up and down many times while x and y move is surface machining.
bool is_freeform(const CuttingPass& pass) {
  double sloped = 0, total = 0;
  int reversals = 0, last_sign = 0;
  for (std::size_t i = 1; i < pass.points.size(); ++i) {
    const auto& a = pass.points[i - 1];
    const auto& b = pass.points[i];
    const double xy = std::hypot(b.x - a.x, b.y - a.y), dz = b.z - a.z;
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
  for (std::size_t i = first_point + 1; i < first_point + path.size() && i < pass.points.size(); ++i) {
    const auto w = pass.point_workingsteps[i];
    if (layer.workingsteps.empty() || layer.workingsteps.back() != w) layer.workingsteps.push_back(w);
  }
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
    for (std::size_t i = 1; i < path.size(); ++i) length += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
  }
  return length;
}

// A short run above the level the pass cuts at, then back down to it (or the end of the pass):
// the tool lifting over a tab or a clamp, part of the lower level.
void merge_tabs(std::vector<Layer>& slices) {
  for (std::size_t k = 1; k < slices.size();) {
    auto& low = slices[k - 1];
    const bool rises = slices[k].z > low.z + kLevelTolerance;
    const bool back = k + 1 == slices.size() || std::abs(slices[k + 1].z - low.z) < kLevelTolerance;
    if (!rises || !back || xy_length(slices[k]) >= xy_length(low)) {
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
    }
    slices.erase(slices.begin() + static_cast<std::ptrdiff_t>(k), slices.begin() + static_cast<std::ptrdiff_t>(last) + 1);
  }
}

// Slices a milling pass at its cutting levels: each run of horizontal moves is a level; the
// moves that descend to it (plunge, ramp, helix) belong to it; moves after the last level
// (a feed retract) belong to the last level.
std::vector<Layer> slice_pass(const CuttingPass& pass, const ToolpathWorkingstep& ws) {
  std::vector<Layer> out;
  if (is_freeform(pass)) {
    Layer layer = make_layer(pass, ws, pass.points, 0);
    layer.freeform = true;
    layer.arcs = pass.arcs;
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
    const bool horizontal = std::abs(b.z - a.z) < kLevelTolerance && std::hypot(b.x - a.x, b.y - a.y) > 0;
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
      for (std::size_t i = piece_first + 1; i < pass.points.size(); ++i) {
        if (out.back().workingsteps.back() < pass.point_workingsteps[i]) {
          out.back().workingsteps.push_back(pass.point_workingsteps[i]);
        }
      }
      out.back().z_top = std::max(out.back().z_top, piece.back().z);
    } else {
      out.push_back(make_layer(pass, ws, piece, piece_first));
    }
  }
  merge_tabs(out);
  for (auto& layer : out) {
    for (const auto& arc : pass.arcs) {
      if (std::min(arc.z_start, arc.z_end) >= layer.z - kLevelTolerance &&
          std::max(arc.z_start, arc.z_end) <= layer.z_top + kLevelTolerance) {
        layer.arcs.push_back(arc);
      }
    }
  }
  return out;
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
    if (std::hypot(p.x - points.front().x, p.y - points.front().y) > 1e-3) return false;
  }
  return true;
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
                                                double chord_tolerance) {
  CutterLocationAnalysis out;
  std::size_t run_begin = 0;  // the first layer of the current run of one tool at one level
  for (const auto& pass : cut_into_passes(workingsteps, chord_tolerance)) {
    const auto& ws = workingsteps[pass.workingstep];
    if (pass.z_only() || (is_hole_making_tool(ws.tool.type) && ws.cycle)) {
      if (pass.z_min >= pass.points.front().z - kLevelTolerance) {
        continue;  // a feed retract out of a hole cuts nothing new
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
      continue;
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
      const bool continues_run = run_begin < out.layers.size() && !layer.freeform &&
                                 !out.layers.back().freeform && out.layers.back().tool.number == layer.tool.number &&
                                 std::abs(out.layers.back().z - layer.z) < kLevelTolerance;
      if (!continues_run) run_begin = out.layers.size();
      out.layers.push_back(std::move(layer));
      for (bool merged = true; merged;) {
        merged = false;
        auto& last = out.layers.back();
        for (std::size_t k = run_begin; k + 1 < out.layers.size(); ++k) {
          if (!boxes_touch(out.layers[k].extent, last.extent)) continue;
          auto& into = out.layers[k];
          for (auto& p : last.paths) into.paths.push_back(std::move(p));
          into.arcs.insert(into.arcs.end(), last.arcs.begin(), last.arcs.end());
          into.workingsteps.insert(into.workingsteps.end(), last.workingsteps.begin(), last.workingsteps.end());
          std::sort(into.workingsteps.begin(), into.workingsteps.end());
          into.workingsteps.erase(std::unique(into.workingsteps.begin(), into.workingsteps.end()), into.workingsteps.end());
          into.z_top = std::max(into.z_top, last.z_top);
          into.extent = path_box(into.paths, r);
          // The merged layer goes last, so that it can absorb the others it now touches.
          Layer moved = std::move(into);
          out.layers.erase(out.layers.begin() + static_cast<std::ptrdiff_t>(k));
          out.layers.back() = std::move(moved);
          merged = true;
          break;
        }
      }
    }
  }
  return out;
}

}  // namespace ncbridge::feature_recognizer
