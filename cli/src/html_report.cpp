#include "html_report.hpp"

#include "html_text.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <string_view>
#include <type_traits>

#include "ncbridge/common/error.hpp"
#include "ncbridge/material_check/feature_region.hpp"

namespace ncbridge::cli {

// Inlined at build time (cli/embed_text.cmake): Debian's three.js with its orbit controls, and
// cli/src/html_viewer.js.
std::string_view three_js();
std::string_view html_viewer_js();

namespace sn = stepnc;
namespace mc = material_check;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kWidthPx = 900;   // drawing width; the height follows the drawing's aspect
constexpr std::size_t kMaxPoints = 200000;  // toolpath points drawn at most (large programs are thinned)

const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                                "#e377c2", "#17becf", "#bcbd22", "#393b79", "#637939", "#8c6d31"};

std::string escape(std::string_view s) { return html_escape(s); }

std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '<') out += "\\u003c";
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
    else out += c;
  }
  return out + "\"";
}

std::string num(double v, int decimals = 3) { return short_number(v, decimals); }

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Program XY -> SVG pixels (y up in the program, down in SVG).
struct View {
  double xmin, ymax, scale, margin = 40;
  double sx(double x) const { return margin + (x - xmin) * scale; }
  double sy(double y) const { return margin + (ymax - y) * scale; }
  std::string pt(double x, double y) const { return num(sx(x), 2) + "," + num(sy(y), 2); }
};

struct Box {
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300, zmin = 1e300, zmax = -1e300;
  void add(double x, double y, double z) {
    xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    zmin = std::min(zmin, z), zmax = std::max(zmax, z);
  }
  bool empty() const { return xmin > xmax; }
};

std::vector<sn::CartesianPoint> points_of(const sn::CompositeCurve& curve) {
  std::vector<sn::CartesianPoint> out;
  for (const auto& segment : curve.segments) {
    if (const auto* line = std::get_if<sn::Polyline>(&segment)) {
      out.insert(out.end(), line->points.begin(), line->points.end());
      continue;
    }
    if (const auto* spline = std::get_if<sn::BSplineCurve>(&segment)) {
      const auto points = sn::bspline_polyline(*spline, 0.01);  // a drawing: a hundredth of a mm is plenty
      out.insert(out.end(), points.begin(), points.end());
      continue;
    }
    const auto& arc = std::get<sn::TrimmedCircle>(segment);
    const auto& p = arc.position;
    const sn::Direction& r = p.ref_direction;
    const sn::Direction y{p.axis.y * r.z - p.axis.z * r.y, p.axis.z * r.x - p.axis.x * r.z, p.axis.x * r.y - p.axis.y * r.x};
    const double sweep = sn::sweep_degrees(arc);
    const int steps = std::max(2, static_cast<int>(std::ceil(sweep / 10)));
    for (int k = 0; k <= steps; ++k) {
      const double t = (arc.trim_1_parameter + (arc.sense_agreement ? 1 : -1) * sweep * k / steps) * kPi / 180;
      out.push_back({p.location.x + arc.radius * (std::cos(t) * r.x + std::sin(t) * y.x),
                     p.location.y + arc.radius * (std::cos(t) * r.y + std::sin(t) * y.y),
                     p.location.z + arc.radius * (std::cos(t) * r.z + std::sin(t) * y.z)});
    }
  }
  return out;
}

const char* kind_colour(std::string_view kind) {
  if (kind == "PLANAR_FACE") return "#555555";
  if (kind == "ROUND_HOLE") return "#b00020";
  if (kind == "CLOSED_POCKET") return "#0047ab";
  if (kind == "OPEN_POCKET") return "#007a5e";
  if (kind == "SLOT") return "#8a2be2";
  if (kind == "STEP") return "#c05000";
  if (kind == "GENERAL_OUTSIDE_PROFILE") return "#000000";
  if (kind == "REGION") return "#808000";
  return "#7f7f7f";  // TOOLPATH_FEATURE: no outline, its toolpath is the feature
}

std::string strategy_name(const sn::Operation& op) {
  return std::visit(
      [](const auto& o) -> std::string {
        using O = std::decay_t<decltype(o)>;
        if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, O>) {
          if (!o.its_machining_strategy) return "";
          return std::visit(
              [](const auto& s) -> std::string {
                using S = std::decay_t<decltype(s)>;
                if constexpr (std::is_same_v<S, sn::Unidirectional>) return "unidirectional";
                else if constexpr (std::is_same_v<S, sn::Bidirectional>) return "bidirectional";
                else if constexpr (std::is_same_v<S, sn::ContourParallel>) return "contour_parallel";
                else if constexpr (std::is_same_v<S, sn::ContourSpiral>) return "contour_spiral";
                else if constexpr (std::is_same_v<S, sn::CenterMilling>) return "center_milling";
                else if constexpr (std::is_same_v<S, sn::BidirectionalContour>) return "bidirectional_contour";
                else return "contour_bidirectional";
              },
              *o.its_machining_strategy);
        } else {
          return "";
        }
      },
      op);
}

struct Path {
  std::vector<sn::CartesianPoint> points;
  bool rapid = false;
  int workingstep = -1;  // index among the drawn workingsteps (colour); -1: a rapid between them
  double low = 0;
};

struct PageFeature {
  std::string id, kind;
  int kind_index = 0;
  std::vector<std::vector<mc::Point2>> rings;  // the outline in program XY (none: a toolpath feature)
  bool located = false;
  double x = 0, y = 0, top = 0, bottom = 0;
  std::string size;  // HTML
  std::vector<std::string> operations;  // HTML, one per workingstep
  std::vector<int> workingsteps;
};

struct PageWorkingstep {
  std::string label;
  int feature = -1;
};

// The page's content: features of the model, workingsteps and toolpaths of the toolpath model.
struct Page {
  std::vector<std::string> kinds;
  std::vector<PageFeature> features;
  std::vector<PageWorkingstep> workingsteps;
  std::vector<Path> paths;
};

int kind_index(Page& page, const std::string& kind) {
  for (std::size_t i = 0; i < page.kinds.size(); ++i) {
    if (page.kinds[i] == kind) return static_cast<int>(i);
  }
  page.kinds.push_back(kind);
  return static_cast<int>(page.kinds.size() - 1);
}

void shape_feature(PageFeature& f, const sn::Feature& feature, std::size_t index, const setup::Stock& stock) {
  if (std::holds_alternative<sn::ToolpathFeature>(feature)) return;
  mc::FeatureRegion region;
  try {
    region = mc::feature_region(feature, index, stock);
  } catch (const InputError&) {
    return;  // listed without an outline (the table says so)
  }
  const double tolerance = std::max({stock.size(0), stock.size(1), 1.0}) / 3000;
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
  for (const auto& curve : region.outline) {
    auto points = curve.points(tolerance);
    if (points.size() < 2) continue;
    for (const auto& p : points) {
      const auto local = region.frame.to_local(p);
      umin = std::min(umin, local.x), umax = std::max(umax, local.x), vmin = std::min(vmin, local.y), vmax = std::max(vmax, local.y);
    }
    f.rings.push_back(std::move(points));
  }
  if (f.rings.empty()) return;
  f.located = true;
  f.top = region.top_z;
  f.bottom = region.floor_z;
  if (region.hole_radius) {
    f.x = region.frame.origin.x, f.y = region.frame.origin.y;
    f.size = "&#8960;" + num(*region.hole_radius * 2, 2);
  } else {
    const auto centre = region.frame.to_program((umin + umax) / 2, (vmin + vmax) / 2);
    f.x = centre.x, f.y = centre.y;
    f.size = num(umax - umin, 2) + " &#215; " + num(vmax - vmin, 2);
  }
}

std::string operation_text(const sn::Project& p, const sn::MachiningWorkingstep& ws) {
  const auto& op = p.operation(ws.its_operation);
  std::string s = escape(ws.its_id) + ": " + escape(lower(sn::entity_name(op))) + " " +
                  escape(p.tool(sn::machining_operation(op).its_tool).its_id);
  const std::string strategy = strategy_name(op);
  if (!strategy.empty()) s += " (" + strategy + ")";
  return s;
}

Page build_page(const sn::Project& model, const sn::Project& toolpaths, const setup::Stock& stock) {
  Page page;
  std::map<std::string, int> feature_by_id;
  for (std::size_t i = 0; i < model.features.size(); ++i) {
    PageFeature f;
    f.id = sn::feature_id(model.features[i]);
    f.kind = std::string(sn::entity_name(model.features[i]));
    f.kind_index = kind_index(page, f.kind);
    shape_feature(f, model.features[i], i, stock);
    feature_by_id.emplace(f.id, static_cast<int>(i));
    page.features.push_back(std::move(f));
  }
  std::map<std::string, const sn::MachiningWorkingstep*> model_workingsteps;
  for (const auto& e : model.main_workplan.its_elements) {
    if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) model_workingsteps.emplace(ws->its_id, ws);
  }

  for (const auto& e : toolpaths.main_workplan.its_elements) {
    if (const auto* r = std::get_if<sn::RapidMovement>(&e)) {
      if (!r->its_toolpath) continue;
      for (const auto& t : r->its_toolpath->its_list) page.paths.push_back({points_of(t.basiccurve), true, -1});
      continue;
    }
    if (const auto* probing = std::get_if<sn::WorkpieceProbing>(&e)) {  // the probe's travel, as a rapid
      const auto& s = probing->start_position.location;
      const auto& d = probing->its_direction;
      const double travel = probing->expected_value.theoretical_size + probing->expected_value.upper_limit;
      page.paths.push_back({{s, {s.x + d.x * travel, s.y + d.y * travel, s.z + d.z * travel}}, true, -1});
      continue;
    }
    const auto& ws = std::get<sn::MachiningWorkingstep>(e);
    const int w = static_cast<int>(page.workingsteps.size());
    const auto& op = sn::machining_operation(toolpaths.operation(ws.its_operation));
    if (op.its_toolpath) {
      for (const auto& t : op.its_toolpath->its_list) {
        const bool rapid = t.its_type == sn::ToolpathType::Connect || t.its_type == sn::ToolpathType::NonContact;
        page.paths.push_back({points_of(t.basiccurve), rapid, w});
      }
    } else if (const auto* hole = std::get_if<sn::RoundHole>(&toolpaths.feature(ws.its_feature))) {
      // A drilling cycle: the drill's axis from the hole's top to its depth (a dot from above).
      const auto& l = hole->feature_placement.location;
      page.paths.push_back({{l, {l.x, l.y, l.z + hole->depth.position.location.z}}, false, w});
    }
    // Its feature in the model: the same workingstep's, else the feature of the same id.
    int feature = -1;
    const sn::Project* described = &toolpaths;
    const sn::MachiningWorkingstep* described_ws = &ws;
    if (&model == &toolpaths) {
      feature = static_cast<int>(ws.its_feature.index);
      described = &model;
    } else if (auto found = model_workingsteps.find(ws.its_id); found != model_workingsteps.end()) {
      feature = static_cast<int>(found->second->its_feature.index);
      described = &model, described_ws = found->second;
    } else if (auto by_id = feature_by_id.find(sn::feature_id(toolpaths.feature(ws.its_feature))); by_id != feature_by_id.end()) {
      feature = by_id->second;
    }
    if (feature >= static_cast<int>(page.features.size())) feature = -1;
    PageWorkingstep step;
    step.feature = feature;
    step.label = operation_text(*described, *described_ws);
    if (feature >= 0) {
      step.label += " &#8212; " + escape(page.features[static_cast<std::size_t>(feature)].id);
      page.features[static_cast<std::size_t>(feature)].workingsteps.push_back(w);
      page.features[static_cast<std::size_t>(feature)].operations.push_back(operation_text(*described, *described_ws));
    }
    page.workingsteps.push_back(std::move(step));
  }
  for (auto& p : page.paths) {
    p.low = 1e300;
    for (const auto& q : p.points) p.low = std::min(p.low, q.z);
  }
  // Features without an outline (TOOLPATH_FEATUREs): placed where their cuts are.
  std::vector<Box> cut_boxes(page.workingsteps.size());
  for (const auto& p : page.paths) {
    if (p.rapid || p.workingstep < 0) continue;
    for (const auto& q : p.points) cut_boxes[static_cast<std::size_t>(p.workingstep)].add(q.x, q.y, q.z);
  }
  for (auto& f : page.features) {
    if (f.located) continue;
    Box b;
    for (int w : f.workingsteps) {
      const Box& c = cut_boxes[static_cast<std::size_t>(w)];
      if (c.empty()) continue;
      b.add(c.xmin, c.ymin, c.zmin);
      b.add(c.xmax, c.ymax, c.zmax);
    }
    if (b.empty()) continue;
    f.x = (b.xmin + b.xmax) / 2, f.y = (b.ymin + b.ymax) / 2, f.top = b.zmax, f.bottom = b.zmin;
    f.size = b.xmax - b.xmin < 0.01 && b.ymax - b.ymin < 0.01 ? std::string("a plunge")
                                                               : "cuts " + num(b.xmax - b.xmin, 2) + " &#215; " + num(b.ymax - b.ymin, 2);
  }
  return page;
}

// A length of 1, 2 or 5 times a power of ten near `target`.
double nice_length(double target) {
  const double p = std::pow(10.0, std::floor(std::log10(std::max(target, 1e-6))));
  for (double k : {1.0, 2.0, 5.0}) {
    if (k * p >= target * 0.7) return k * p;
  }
  return 10 * p;
}

}  // namespace

std::string html_report(const HtmlReportInput& in) {
  const sn::Project& model = *in.model;
  const sn::Project& drawn = in.toolpaths ? *in.toolpaths : model;

  // The box: the stock, or the toolpaths' extent.
  Box extent;
  setup::Stock stock;
  if (in.stock) stock = *in.stock;
  Page page = build_page(model, drawn, in.stock ? stock : setup::Stock{});
  for (const auto& p : page.paths) {
    for (const auto& q : p.points) extent.add(q.x, q.y, q.z);
  }
  if (!in.stock) {
    if (extent.empty()) extent.add(0, 0, 0);
    stock.min = {extent.xmin, extent.ymin, extent.zmin};
    stock.max = {extent.xmax, extent.ymax, std::max(extent.zmax, extent.zmin + 1e-3)};
    page = build_page(model, drawn, stock);  // the outlines of steps and profiles reach the stock's edges
  }
  extent.add(stock.min[0], stock.min[1], stock.min[2]);
  extent.add(stock.max[0], stock.max[1], stock.max[2]);
  for (const auto& f : page.features) {
    for (const auto& ring : f.rings) {
      for (const auto& q : ring) extent.add(q.x, q.y, f.bottom);
    }
  }
  // The program zero is drawn (axes) when it lies near the drawing.
  const double reach = std::max(extent.xmax - extent.xmin, extent.ymax - extent.ymin);
  const bool show_origin = extent.xmin - 0.25 * reach <= 0 && 0 <= extent.xmax + 0.25 * reach && extent.ymin - 0.25 * reach <= 0 &&
                           0 <= extent.ymax + 0.25 * reach;
  if (show_origin) extent.add(0, 0, extent.zmin);
  const double w = std::max(extent.xmax - extent.xmin, 1e-3), h = std::max(extent.ymax - extent.ymin, 1e-3);
  View v{extent.xmin, extent.ymax, kWidthPx / w};
  const double height_px = h * v.scale + 2 * v.margin, width_px = kWidthPx + 2 * v.margin;
  std::size_t total_points = 0;
  for (const auto& p : page.paths) total_points += p.points.size();
  // Thinning: skip points closer than `thin` to the last drawn one when the program is large.
  const double thin = total_points > kMaxPoints ? std::sqrt(static_cast<double>(total_points) / kMaxPoints) * 0.5 / v.scale : 0;
  auto thinned = [&](const Path& p, auto&& emit) {
    double lx = 1e300, ly = 1e300;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      const auto& q = p.points[i];
      if (thin > 0 && i > 0 && i + 1 < p.points.size() && std::hypot(q.x - lx, q.y - ly) < thin) continue;
      emit(q);
      lx = q.x, ly = q.y;
    }
  };
  auto colour_of = [](int ws) { return kPalette[static_cast<std::size_t>(ws) % std::size(kPalette)]; };

  std::string svg;
  svg += "<svg id=\"top\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + num(width_px, 0) + " " + num(height_px, 0) +
         "\" width=\"" + num(width_px, 0) + "\" height=\"" + num(height_px, 0) + "\" data-scale=\"" + num(v.scale, 6) +
         "\" data-x0=\"" + num(v.xmin, 6) + "\" data-y0=\"" + num(v.ymax, 6) + "\" data-margin=\"" + num(v.margin) + "\">\n";
  svg += "<rect class=\"stock\" x=\"" + num(v.sx(stock.min[0]), 2) + "\" y=\"" + num(v.sy(stock.max[1]), 2) + "\" width=\"" +
         num(stock.size(0) * v.scale, 2) + "\" height=\"" + num(stock.size(1) * v.scale, 2) +
         "\" fill=\"#f4f1ea\" stroke=\"#999\" stroke-width=\"1\"/>\n";
  if (!show_origin || std::abs(stock.min[0]) > 1e-6 || std::abs(stock.min[1]) > 1e-6) {  // else the axes mark it
    svg += "<text x=\"" + num(v.sx(stock.min[0]), 2) + "\" y=\"" + num(v.sy(stock.min[1]) + 14, 2) + "\" class=\"axis\">X" +
           num(stock.min[0], 2) + " Y" + num(stock.min[1], 2) + "</text>\n";
  }
  svg += "<text x=\"" + num(v.sx(stock.max[0]), 2) + "\" y=\"" + num(v.sy(stock.max[1]) - 6, 2) +
         "\" class=\"axis\" text-anchor=\"end\">X" + num(stock.max[0], 2) + " Y" + num(stock.max[1], 2) + "</text>\n";
  if (show_origin) {
    const double arrow = nice_length(reach / 8);
    const double ox = v.sx(0), oy = v.sy(0), len = arrow * v.scale;
    svg += "<g class=\"axes\" stroke-width=\"1.5\"><line x1=\"" + num(ox, 2) + "\" y1=\"" + num(oy, 2) + "\" x2=\"" + num(ox + len, 2) +
           "\" y2=\"" + num(oy, 2) + "\" stroke=\"#d00\" marker-end=\"url(#ax)\"/><line x1=\"" + num(ox, 2) + "\" y1=\"" + num(oy, 2) +
           "\" x2=\"" + num(ox, 2) + "\" y2=\"" + num(oy - len, 2) + "\" stroke=\"#080\" marker-end=\"url(#ay)\"/>"
           "<text x=\"" + num(ox + len + 4, 2) + "\" y=\"" + num(oy + 4, 2) + "\" fill=\"#d00\" class=\"axis\">X</text><text x=\"" +
           num(ox - 4, 2) + "\" y=\"" + num(oy - len - 6, 2) + "\" fill=\"#080\" class=\"axis\">Y</text>"
           "<circle cx=\"" + num(ox, 2) + "\" cy=\"" + num(oy, 2) + "\" r=\"2.5\" fill=\"#333\"/></g>\n"
           "<defs><marker id=\"ax\" markerWidth=\"8\" markerHeight=\"8\" refX=\"6\" refY=\"3\" orient=\"auto\"><path d=\"M0,0 L6,3 L0,6 z\" "
           "fill=\"#d00\"/></marker><marker id=\"ay\" markerWidth=\"8\" markerHeight=\"8\" refX=\"6\" refY=\"3\" orient=\"auto\">"
           "<path d=\"M0,0 L6,3 L0,6 z\" fill=\"#080\"/></marker></defs>\n";
  }
  svg += "<g id=\"paths\" fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  for (const auto& p : page.paths) {
    if (p.points.empty()) continue;
    std::string pts;
    thinned(p, [&](const sn::CartesianPoint& q) { pts += v.pt(q.x, q.y) + " "; });
    const std::string attrs = "data-low=\"" + num(p.low) + "\"" + (p.workingstep >= 0 ? " data-ws=\"" + std::to_string(p.workingstep) + "\"" : "");
    if (p.rapid) {
      svg += "<polyline class=\"rp\" " + attrs + " points=\"" + pts + "\" stroke=\"#888\" stroke-width=\"0.7\" stroke-dasharray=\"4 3\"/>\n";
    } else {
      svg += "<polyline class=\"cut\" " + attrs + " points=\"" + pts + "\" stroke=\"" + colour_of(p.workingstep) +
             "\" stroke-width=\"1.2\"/>\n";
      if (p.points.size() == 2 && p.points[0].x == p.points[1].x && p.points[0].y == p.points[1].y) {
        svg += "<circle class=\"cut\" " + attrs + " cx=\"" + num(v.sx(p.points[0].x), 2) + "\" cy=\"" + num(v.sy(p.points[0].y), 2) +
               "\" r=\"2.5\" fill=\"" + colour_of(p.workingstep) + "\"/>\n";
      }
    }
  }
  svg += "</g>\n<g id=\"outlines\" fill=\"none\" stroke-width=\"2.2\" stroke-dasharray=\"8 4\">\n";
  for (std::size_t i = 0; i < page.features.size(); ++i) {
    const auto& f = page.features[i];
    if (f.rings.empty()) continue;
    std::string d;
    for (const auto& ring : f.rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) d += (k ? "L" : "M") + v.pt(ring[k].x, ring[k].y);
      d += "Z";
    }
    svg += "<g id=\"f" + std::to_string(i) + "\" class=\"ol\" data-k=\"" + std::to_string(f.kind_index) + "\" stroke=\"" +
           kind_colour(f.kind) + "\"><title>" + escape(f.id) + " (" + escape(lower(f.kind)) + ")</title><path d=\"" + d + "\"/></g>\n";
  }
  svg += "</g>\n<g id=\"labels\">\n";
  // Labels at the outlined features' centres, moved down a line while they would cover an earlier one.
  std::vector<std::pair<double, double>> placed;
  for (std::size_t i = 0; i < page.features.size(); ++i) {
    const auto& f = page.features[i];
    if (f.rings.empty()) continue;
    const double x = v.sx(f.x);
    double y = v.sy(f.y);
    const double half_width = 3.6 * static_cast<double>(f.id.size());
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [px, py] : placed) {
        if (std::abs(py - y) < 14 && std::abs(px - x) < half_width + 40) {
          y = py + 15;
          moved = true;
        }
      }
    }
    placed.emplace_back(x, y);
    svg += "<text class=\"label\" data-f=\"" + std::to_string(i) + "\" data-k=\"" + std::to_string(f.kind_index) + "\" x=\"" +
           num(x, 2) + "\" y=\"" + num(y, 2) + "\" fill=\"" + kind_colour(f.kind) + "\">" + escape(f.id) + "</text>\n";
  }
  svg += "</g>\n</svg>\n";

  // The toolbar (legend and toggles) above the drawing.
  double zmin = extent.zmin, zmax = extent.zmax;
  std::string toolbar = "<div class=\"toolbar\" id=\"toolbar\"><span class=\"tb-title\">Feature kinds</span> ";
  for (std::size_t k = 0; k < page.kinds.size(); ++k) {
    std::size_t n = 0;
    for (const auto& f : page.features) n += f.kind_index == static_cast<int>(k);
    toolbar += "<label class=\"kind\"><input type=\"checkbox\" checked data-kind=\"" + std::to_string(k) + "\"> <span class=\"ksw\" style=\"border-color:" +
               std::string(kind_colour(page.kinds[k])) + "\"></span>" + escape(lower(page.kinds[k])) + " (" + std::to_string(n) + ")</label> ";
  }
  toolbar += "<br><label><input type=\"checkbox\" id=\"show-cuts\" checked> <span class=\"lsw cutsw\"></span>cutting moves (colour per workingstep)</label> "
             "<label><input type=\"checkbox\" id=\"show-rapids\" checked> <span class=\"lsw rapidsw\"></span>rapid and non-cutting moves</label> "
             "<label><input type=\"checkbox\" id=\"show-features\" checked> <span class=\"lsw olsw\"></span>feature outlines</label> "
             "<label><input type=\"checkbox\" id=\"show-labels\" checked> labels</label><br>"
             "<label>lowest Z shown <input type=\"range\" id=\"zcut\" min=\"" + num(zmin - 0.001) + "\" max=\"" + num(zmax) +
             "\" step=\"any\" value=\"" + num(zmin - 0.001) + "\"> <output id=\"zcut-value\">all</output></label> "
             "<label><input type=\"checkbox\" id=\"zband\"> only that layer (&#177;0.05 mm)</label></div>\n";

  // Side panel: setup warnings first, where they cannot be missed.
  std::string panel;
  if (!in.setup_warnings.empty()) {
    panel += "<div class=\"setup\"><h2>Check the setup (" + std::to_string(in.setup_warnings.size()) +
             (in.setup_warnings.size() == 1 ? " warning" : " warnings") + ")</h2>\n<ul>\n";
    for (const auto& warning : in.setup_warnings) panel += "<li>" + escape(warning) + "</li>\n";
    panel += "</ul></div>\n";
  }
  panel += "<h2>Features (" + std::to_string(page.features.size()) + ") <span class=\"note\">click a row: the feature and its toolpaths</span></h2>\n"
           "<table id=\"features\"><tr><th>id</th><th>kind</th><th>centre mm</th><th>Z top / bottom</th><th>size mm</th><th>workingsteps</th></tr>\n";
  for (std::size_t i = 0; i < page.features.size(); ++i) {
    const auto& f = page.features[i];
    std::string ops;
    for (const auto& op : f.operations) ops += op + "<br>";
    const std::string where = f.located || !f.size.empty() ? num(f.x, 2) + ", " + num(f.y, 2) : "&#8212;";
    const std::string z = f.located || !f.size.empty() ? num(f.top, 2) + " / " + num(f.bottom, 2) : "&#8212;";
    std::string size = f.size.empty() ? "&#8212;" : f.size;
    if (f.rings.empty() && f.kind != "TOOLPATH_FEATURE") size += " <span class=\"note\">(no outline: its geometry could not be drawn)</span>";
    panel += "<tr data-f=\"" + std::to_string(i) + "\" data-k=\"" + std::to_string(f.kind_index) + "\"><td><span class=\"ksw\" style=\"border-color:" +
             std::string(kind_colour(f.kind)) + "\"></span>" + escape(f.id) + "</td><td>" + escape(lower(f.kind)) + "</td><td>" + where +
             "</td><td>" + z + "</td><td>" + size + "</td><td>" + ops + "</td></tr>\n";
  }
  panel += "</table>\n<h2>Workingsteps (" + std::to_string(page.workingsteps.size()) +
           ") <span class=\"note\">toggle; hover: highlight</span></h2>\n<ul class=\"legend\" id=\"workingsteps\">\n";
  for (std::size_t i = 0; i < page.workingsteps.size(); ++i) {
    panel += "<li data-ws=\"" + std::to_string(i) + "\"><label><input type=\"checkbox\" checked data-ws=\"" + std::to_string(i) +
             "\"> <span class=\"sw\" style=\"background:" + colour_of(static_cast<int>(i)) + "\"></span>" + page.workingsteps[i].label +
             "</label></li>\n";
  }
  panel += "</ul>\n<h2>Tools</h2>\n<table><tr><th>id</th><th>&#8960; mm</th></tr>\n";
  for (const auto& t : drawn.tools) panel += "<tr><td>" + escape(t.its_id) + "</td><td>" + num(t.dimension.diameter) + "</td></tr>\n";
  panel += "</table>\n<h2>Warnings (" + std::to_string(in.setup_warnings.size() + in.warnings.size()) + ")</h2>\n<ul>\n";
  for (const auto& warning : in.setup_warnings) panel += "<li>" + escape(warning) + "</li>\n";
  for (const auto& warning : in.warnings) panel += "<li>" + escape(warning) + "</li>\n";
  if (in.warnings.empty() && in.setup_warnings.empty()) panel += "<li>none</li>\n";
  panel += "</ul>\n";
  if (thin > 0) panel += "<p class=\"note\">Toolpaths thinned for display (" + std::to_string(total_points) + " points).</p>\n";

  // The views' data: toolpaths (x,y,z triples, thinned like the drawing), outlined features,
  // the feature of each workingstep, the kind of each feature.
  std::string data = "{\"stock\":{\"min\":[" + num(stock.min[0]) + "," + num(stock.min[1]) + "," + num(stock.min[2]) + "],\"max\":[" +
                     num(stock.max[0]) + "," + num(stock.max[1]) + "," + num(stock.max[2]) + "]},\"colours\":[";
  for (std::size_t i = 0; i < std::size(kPalette); ++i) data += std::string(i ? "," : "") + "\"" + kPalette[i] + "\"";
  data += "],\"wsf\":[";
  for (std::size_t i = 0; i < page.workingsteps.size(); ++i) data += (i ? "," : "") + std::to_string(page.workingsteps[i].feature);
  data += "],\"fk\":[";
  for (std::size_t i = 0; i < page.features.size(); ++i) data += (i ? "," : "") + std::to_string(page.features[i].kind_index);
  data += "],\"paths\":[";
  bool first = true;
  for (const auto& p : page.paths) {
    if (p.points.empty()) continue;
    std::string pts;
    thinned(p, [&](const sn::CartesianPoint& q) { pts += (pts.empty() ? "" : ",") + num(q.x) + "," + num(q.y) + "," + num(q.z); });
    data += std::string(first ? "" : ",") + "{\"w\":" + std::to_string(p.workingstep) + ",\"r\":" + (p.rapid ? "1" : "0") + ",\"p\":[" + pts + "]}";
    first = false;
  }
  data += "],\"features\":[";
  first = true;
  for (std::size_t i = 0; i < page.features.size(); ++i) {
    const auto& f = page.features[i];
    if (f.rings.empty()) continue;
    data += std::string(first ? "" : ",") + "{\"i\":" + std::to_string(i) + ",\"id\":" + json_string(f.id) + ",\"t\":" + num(f.top) +
            ",\"b\":" + num(f.bottom) + ",\"col\":\"" + kind_colour(f.kind) + "\",\"rings\":[";
    for (std::size_t r = 0; r < f.rings.size(); ++r) {
      data += r ? ",[" : "[";
      for (std::size_t k = 0; k < f.rings[r].size(); ++k) data += (k ? "," : "") + num(f.rings[r][k].x) + "," + num(f.rings[r][k].y);
      data += "]";
    }
    data += "]}";
    first = false;
  }
  data += "]}";
  const std::string view3d =
      "<h2>3D view <span class=\"note\">drag: turn &#183; right drag or shift drag: pan &#183; wheel: zoom &#183; mm, "
      "axes at the program zero: X red, Y green, Z blue &#183; grid 10 mm</span></h2>\n"
      "<div class=\"controls\"><button data-view=\"iso\">iso</button> <button data-view=\"top\">top</button> "
      "<button data-view=\"front\">front</button> <button data-view=\"side\">side</button></div>\n"
      "<div id=\"view3d\"></div><p id=\"view3d-status\" class=\"note\"></p>\n"
      "<script type=\"application/json\" id=\"ncb-data\">" + data + "</script>\n";
  // At the end of the body: the views are sized once the side panel is laid out.
  const std::string scripts =
      "<script>\n" + std::string(three_js()) + "\n</script>\n<script>\n" + std::string(html_viewer_js()) + "\n</script>\n";

  std::string html;
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>ncbridge " + escape(in.level) + ": " + escape(in.title) +
          "</title>\n<style>\n"
          "body{margin:0;font:12px/1.35 system-ui,sans-serif;color:#222;display:flex;min-height:100vh}\n"
          "main{flex:1 1 auto;padding:12px;overflow:auto;min-width:0}\n"
          "aside{flex:0 0 560px;padding:12px 16px;border-left:1px solid #ccc;background:#fafafa;overflow:auto;max-height:100vh;box-sizing:border-box}\n"
          "h1{font-size:16px;margin:0 0 8px}h2{font-size:14px;margin:14px 0 6px}\n"
          "table{border-collapse:collapse;width:100%;table-layout:fixed}td,th{border-bottom:1px solid #e2e2e2;padding:2px 4px;"
          "text-align:left;vertical-align:top;overflow-wrap:anywhere}\n"
          "ul{padding-left:18px;margin:4px 0}.legend{list-style:none;padding:0}\n"
          ".sw{display:inline-block;width:12px;height:12px;margin-right:6px;vertical-align:middle}\n"
          ".ksw{display:inline-block;width:14px;height:10px;margin-right:5px;vertical-align:middle;border:2px dashed;box-sizing:border-box}\n"
          ".lsw{display:inline-block;width:22px;height:0;margin-right:5px;vertical-align:middle;border-top:2px solid #1f77b4}\n"
          ".rapidsw{border-top:1px dashed #888}.olsw{border-top:2px dashed #0047ab}\n"
          ".toolbar{margin:0 0 6px;line-height:1.9}.toolbar label{margin-right:10px;white-space:nowrap}.tb-title{font-weight:600;margin-right:6px}\n"
          "#view3d{width:100%;height:520px;border:1px solid #ccc;background:#fff}.controls{margin:4px 0}.controls button{font:inherit}\n"
          "#features th:nth-child(1){width:20%}#features th:nth-child(2){width:14%}#features th:nth-child(3){width:11%}"
          "#features th:nth-child(4){width:11%}#features th:nth-child(5){width:12%}\n"
          "tr[data-f]{cursor:pointer}tr.hl{background:#fff3b0}li.hl{background:#fff3b0}\n"
          "#drawing{position:relative;border:1px solid #ddd;background:#fff;overflow:hidden}\n"
          "#top{cursor:grab;display:block;width:100%;height:auto}#top polyline,#top path,#top line,#top rect{vector-effect:non-scaling-stroke}\n"
          "#top g.hl{stroke-width:5;stroke-dasharray:none}#top .dim{opacity:0.1}#top .off{display:none}\n"
          "#top .label{font:bold 12px system-ui,sans-serif;text-anchor:middle;dominant-baseline:middle;paint-order:stroke;stroke:#fff;stroke-width:3px}\n"
          "#top .axis{font:12px system-ui,sans-serif;fill:#666}\n"
          "#scalebar{position:absolute;right:12px;bottom:10px;font:11px system-ui,sans-serif;background:rgba(255,255,255,.85);padding:2px 4px}\n"
          "#scalebar div{height:5px;border:1.5px solid #222;border-top:none}\n"
          "#pointer{position:absolute;right:10px;top:6px;font:11px ui-monospace,monospace;background:rgba(255,255,255,.85);padding:2px 4px}\n"
          ".note{color:#666;font-weight:normal}.setup{border:2px solid #c0392b;background:#fdecea;padding:4px 10px;margin-bottom:8px}\n"
          ".setup h2{color:#c0392b;margin-top:4px}\n"
          "body.picture aside,body.picture h1,body.picture h2,body.picture .toolbar,body.picture .controls,body.picture #view3d,"
          "body.picture #view3d-status,body.picture #pointer{display:none}body.picture main,body.picture3d main{padding:0}"
          "body.picture #drawing{border:none}body.picture #top{width:100vw;height:100vh}\n"
          "body.picture3d aside,body.picture3d h1,body.picture3d h2,body.picture3d .toolbar,body.picture3d .controls,"
          "body.picture3d #drawing,body.picture3d #view3d-status{display:none}body.picture3d #view3d{width:100vw;height:100vh;border:none}\n</style>\n</head>\n<body>\n<main>\n<h1>" +
          escape(in.title) + " &#8212; " + escape(in.level) + ", top view <span class=\"note\">mm &#183; wheel: zoom &#183; drag: pan &#183; double click: whole view</span></h1>\n" +
          toolbar + "<div id=\"drawing\">" + svg + "<div id=\"scalebar\"><div></div><span></span></div><div id=\"pointer\"></div></div>\n" +
          view3d + "</main>\n<aside>\n" + panel + "</aside>\n" + scripts + "</body>\n</html>\n";
  return html;
}

}  // namespace ncbridge::cli
