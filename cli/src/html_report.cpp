#include "html_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace ncbridge::cli {

// Inlined at build time (cli/embed_text.cmake): Debian's three.js with its orbit controls, and
// cli/src/html_viewer.js.
std::string_view three_js();
std::string_view html_viewer_js();

namespace fr = feature_recognizer;
namespace sn = stepnc;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kWidthPx = 900;   // drawing width; the height follows the stock's aspect
constexpr std::size_t kMaxPoints = 200000;  // toolpath points drawn at most (large programs are thinned)

const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                                "#e377c2", "#17becf", "#bcbd22", "#393b79", "#637939", "#8c6d31"};

std::string escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string num(double v, int decimals = 3) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

// Program XY -> SVG pixels (y up in the program, down in SVG).
struct View {
  double xmin, ymax, scale, margin = 30;
  double sx(double x) const { return margin + (x - xmin) * scale; }
  double sy(double y) const { return margin + (ymax - y) * scale; }
  std::string pt(double x, double y) const { return num(sx(x), 2) + "," + num(sy(y), 2); }
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

struct Path {
  std::vector<sn::CartesianPoint> points;
  bool rapid = false;
  std::size_t workingstep = 0;  // index among drawn workingsteps (colour)
};

std::string feature_outline(const fr::RecognizedFeature& f, const View& v) {
  const auto& p = f.profile;
  const double a = p.angle_deg * kPi / 180;
  auto rect = [&](double length, double width, double radius) {
    const double rx = std::min(radius, std::min(length, width) / 2) * v.scale;
    return "<rect x=\"" + num(v.sx(f.x) - length / 2 * v.scale, 2) + "\" y=\"" + num(v.sy(f.y) - width / 2 * v.scale, 2) +
           "\" width=\"" + num(length * v.scale, 2) + "\" height=\"" + num(width * v.scale, 2) + "\" rx=\"" + num(rx, 2) +
           "\" transform=\"rotate(" + num(-p.angle_deg, 4) + " " + v.pt(f.x, f.y) + ")\"/>";
  };
  auto polygon = [&](const std::vector<fr::Point2>& ring) {
    std::string s = "<polygon points=\"";
    for (const auto& q : ring) s += v.pt(q.x, q.y) + " ";
    return s + "\"/>";
  };
  (void)a;
  switch (f.type) {
    case fr::FeatureType::RoundHole:
      return "<circle cx=\"" + num(v.sx(f.x), 2) + "\" cy=\"" + num(v.sy(f.y), 2) + "\" r=\"" + num(f.diameter / 2 * v.scale, 2) + "\"/>";
    case fr::FeatureType::Slot: {
      if (f.slot_course.size() < 2) break;
      const auto& s0 = f.slot_course.front();
      const auto& s1 = f.slot_course.back();
      const double length = std::hypot(s1.x - s0.x, s1.y - s0.y);
      const bool radiused = f.slot_ends[0] == fr::SlotEnd::Radiused;
      const double total = radiused ? length + f.slot_width : length;
      const double angle = std::atan2(s1.y - s0.y, s1.x - s0.x) * 180 / kPi;
      fr::RecognizedFeature g = f;
      g.x = (s0.x + s1.x) / 2, g.y = (s0.y + s1.y) / 2;
      g.profile.angle_deg = angle;
      const double rx = radiused ? f.slot_width / 2 : 0;
      return "<rect x=\"" + num(v.sx(g.x) - total / 2 * v.scale, 2) + "\" y=\"" + num(v.sy(g.y) - f.slot_width / 2 * v.scale, 2) +
             "\" width=\"" + num(total * v.scale, 2) + "\" height=\"" + num(f.slot_width * v.scale, 2) + "\" rx=\"" +
             num(rx * v.scale, 2) + "\" transform=\"rotate(" + num(-angle, 4) + " " + v.pt(g.x, g.y) + ")\"/>";
    }
    default: break;
  }
  if (p.shape == fr::ProfileShape::Circular) {
    return "<circle cx=\"" + num(v.sx(f.x), 2) + "\" cy=\"" + num(v.sy(f.y), 2) + "\" r=\"" + num(p.diameter / 2 * v.scale, 2) + "\"/>";
  }
  if (p.shape == fr::ProfileShape::Rectangular || (p.outline.empty() && p.length > 0)) return rect(p.length, p.width, p.corner_radius);
  if (!p.outline.empty()) return polygon(p.outline);
  return "";
}

const char* feature_colour(fr::FeatureType t);

// A feature for the 3D view (JSON): its outline in XY ("c": circle, "r": rectangle, "p":
// polygon) from its top to its bottom.
std::string feature_json(const fr::RecognizedFeature& f, const std::string& id) {
  const auto& p = f.profile;
  std::string shape;
  if (f.type == fr::FeatureType::RoundHole) {
    shape = "\"k\":\"c\",\"d\":" + num(f.diameter);
  } else if (f.type == fr::FeatureType::Slot && f.slot_course.size() >= 2) {
    const auto& s0 = f.slot_course.front();
    const auto& s1 = f.slot_course.back();
    const double length = std::hypot(s1.x - s0.x, s1.y - s0.y) + (f.slot_ends[0] == fr::SlotEnd::Radiused ? f.slot_width : 0);
    shape = "\"k\":\"r\",\"cx\":" + num((s0.x + s1.x) / 2) + ",\"cy\":" + num((s0.y + s1.y) / 2) + ",\"l\":" + num(length) +
            ",\"w\":" + num(f.slot_width) + ",\"a\":" + num(std::atan2(s1.y - s0.y, s1.x - s0.x) * 180 / kPi);
  } else if (p.shape == fr::ProfileShape::Circular) {
    shape = "\"k\":\"c\",\"d\":" + num(p.diameter);
  } else if (p.shape == fr::ProfileShape::Rectangular || (p.outline.empty() && p.length > 0)) {
    shape = "\"k\":\"r\",\"l\":" + num(p.length) + ",\"w\":" + num(p.width) + ",\"a\":" + num(p.angle_deg);
  } else if (!p.outline.empty()) {
    shape = "\"k\":\"p\",\"ring\":[";
    for (std::size_t i = 0; i < p.outline.size(); ++i) shape += (i ? "," : "") + num(p.outline[i].x) + "," + num(p.outline[i].y);
    shape += "]";
  } else {
    return "";
  }
  std::string json_id;
  for (char c : id) {
    if (c == '"' || c == '\\') json_id += '\\';
    if (c == '<') json_id += "\\u003c"; else json_id += c;
  }
  return "{\"id\":\"" + json_id + "\",\"x\":" + num(f.x) + ",\"y\":" + num(f.y) + ",\"t\":" + num(f.top_z) + ",\"b\":" +
         num(f.bottom_z) + ",\"col\":\"" + feature_colour(f.type) + "\"," + shape + "}";
}

const char* feature_colour(fr::FeatureType t) {
  switch (t) {
    case fr::FeatureType::PlanarFace: return "#555555";
    case fr::FeatureType::RoundHole: return "#b00020";
    case fr::FeatureType::ClosedPocket: return "#0047ab";
    case fr::FeatureType::OpenPocket: return "#007a5e";
    case fr::FeatureType::Slot: return "#8a2be2";
    case fr::FeatureType::Step: return "#c05000";
    case fr::FeatureType::GeneralOutsideProfile: return "#000000";
    case fr::FeatureType::Region: return "#808000";
  }
  return "#000000";
}

std::string dims_text(const fr::RecognizedFeature& f) {
  const auto& p = f.profile;
  switch (f.type) {
    case fr::FeatureType::RoundHole: return "&#8960;" + num(f.diameter, 2);
    case fr::FeatureType::Slot: return "w " + num(f.slot_width, 2);
    default: break;
  }
  if (p.shape == fr::ProfileShape::Circular) return "&#8960;" + num(p.diameter, 2);
  std::string s = num(p.length, 2) + " &#215; " + num(p.width, 2);
  if (p.shape == fr::ProfileShape::Rectangular && p.corner_radius > 0.01) s += " r" + num(p.corner_radius, 2);
  if (p.corner_chamfer > 0.01) s += " chamfer " + num(p.corner_chamfer, 2) + " &#215; 45&#176;";
  return s;
}

}  // namespace

std::string html_report(const HtmlReportInput& in) {
  const Cc2Output& cc2 = *in.cc2;
  const auto& stock = cc2.stock;
  const auto& project = cc2.project;

  // Toolpaths per machining workingstep (and rapid movements between them).
  std::vector<Path> paths;
  std::vector<std::string> legend;
  std::size_t total_points = 0;
  for (const auto& e : project.main_workplan.its_elements) {
    if (const auto* r = std::get_if<sn::RapidMovement>(&e)) {
      if (!r->its_toolpath) continue;
      for (const auto& t : r->its_toolpath->its_list) paths.push_back({points_of(t.basiccurve), true, legend.size()});
      continue;
    }
    if (const auto* probing = std::get_if<sn::WorkpieceProbing>(&e)) {  // the probe's travel, as a rapid
      const auto& s = probing->start_position.location;
      const auto& d = probing->its_direction;
      const double travel = probing->expected_value.theoretical_size + probing->expected_value.upper_limit;
      paths.push_back({{s, {s.x + d.x * travel, s.y + d.y * travel, s.z + d.z * travel}}, true, legend.size()});
      continue;
    }
    const auto& ws = std::get<sn::MachiningWorkingstep>(e);
    const auto& op = sn::machining_operation(project.operation(ws.its_operation));
    if (op.its_toolpath) {
      for (const auto& t : op.its_toolpath->its_list) {
        const bool rapid = t.its_type == sn::ToolpathType::Connect || t.its_type == sn::ToolpathType::NonContact;
        paths.push_back({points_of(t.basiccurve), rapid, legend.size()});
      }
    } else if (const auto* hole = std::get_if<sn::RoundHole>(&project.feature(ws.its_feature))) {
      // A drilling cycle: the drill's axis from the hole's top to its depth (a dot from above).
      const auto& l = hole->feature_placement.location;
      paths.push_back({{l, {l.x, l.y, l.z + hole->depth.position.location.z}}, false, legend.size()});
    }
    legend.push_back(ws.its_id + " — " + std::string(sn::entity_name(project.operation(ws.its_operation))) + " — " +
                     project.tool(op.its_tool).its_id);
  }
  for (const auto& p : paths) total_points += p.points.size();

  // The view: the stock and everything the tool went over (a profile's path lies outside it).
  double xmin = stock.min[0], xmax = stock.max[0], ymin = stock.min[1], ymax = stock.max[1];
  for (const auto& p : paths) {
    for (const auto& q : p.points) {
      xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x), ymin = std::min(ymin, q.y), ymax = std::max(ymax, q.y);
    }
  }
  const double w = std::max(xmax - xmin, 1e-3), h = std::max(ymax - ymin, 1e-3);
  View v{xmin, ymax, kWidthPx / w};
  const double height_px = h * v.scale + 2 * v.margin, width_px = kWidthPx + 2 * v.margin;
  // Thinning: skip points closer than `step` to the last drawn one when the program is large.
  const double thin = total_points > kMaxPoints ? std::sqrt(static_cast<double>(total_points) / kMaxPoints) * 0.5 / v.scale : 0;

  std::string svg;
  svg += "<svg id=\"top\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + num(width_px, 0) + " " + num(height_px, 0) +
         "\" width=\"" + num(width_px, 0) + "\" height=\"" + num(height_px, 0) + "\">\n";
  svg += "<rect x=\"" + num(v.sx(stock.min[0]), 2) + "\" y=\"" + num(v.sy(stock.max[1]), 2) + "\" width=\"" +
         num(stock.size(0) * v.scale, 2) + "\" height=\"" + num(stock.size(1) * v.scale, 2) +
         "\" fill=\"#f4f1ea\" stroke=\"#999\" stroke-width=\"1\"/>\n";
  svg += "<text x=\"" + num(v.sx(stock.min[0]), 2) + "\" y=\"" + num(v.sy(stock.max[1]) - 8, 2) + "\" class=\"axis\">stock " +
         num(stock.size(0)) + " &#215; " + num(stock.size(1)) + " &#215; " + num(stock.size(2)) + " mm, X &#8594; Y &#8593;</text>\n";
  svg += "<g fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  for (const auto& p : paths) {
    if (p.points.empty()) continue;
    std::string pts;
    double lx = 1e300, ly = 1e300;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      const auto& q = p.points[i];
      if (thin > 0 && i + 1 < p.points.size() && std::hypot(q.x - lx, q.y - ly) < thin) continue;
      pts += v.pt(q.x, q.y) + " ";
      lx = q.x, ly = q.y;
    }
    if (p.rapid) {
      svg += "<polyline points=\"" + pts + "\" stroke=\"#aaa\" stroke-width=\"0.6\" stroke-dasharray=\"3 3\"/>\n";
    } else {
      svg += "<polyline class=\"ws" + std::to_string(p.workingstep) + "\" points=\"" + pts + "\" stroke=\"" +
             kPalette[p.workingstep % std::size(kPalette)] + "\" stroke-width=\"1\" stroke-opacity=\"0.75\"/>\n";
      if (p.points.size() == 2 && p.points[0].x == p.points[1].x && p.points[0].y == p.points[1].y) {
        svg += "<circle cx=\"" + num(v.sx(p.points[0].x), 2) + "\" cy=\"" + num(v.sy(p.points[0].y), 2) + "\" r=\"2.5\" fill=\"" +
               kPalette[p.workingstep % std::size(kPalette)] + "\"/>\n";
      }
    }
  }
  svg += "</g>\n<g fill=\"none\" stroke-width=\"2.5\" stroke-dasharray=\"8 4\">\n";
  for (std::size_t i = 0; i < cc2.features.size(); ++i) {
    const auto& f = cc2.features[i];
    const std::string outline = feature_outline(f, v);
    if (outline.empty()) continue;
    svg += "<g id=\"f" + std::to_string(i) + "\" stroke=\"" + std::string(feature_colour(f.type)) + "\"><title>" + escape(cc2.feature_ids[i]) + "</title>" + outline + "</g>\n";
  }
  svg += "</g>\n";
  // Labels at the features' centres, moved down a line while they would cover an earlier one.
  std::vector<std::pair<double, double>> placed;
  for (std::size_t i = 0; i < cc2.features.size(); ++i) {
    const auto& f = cc2.features[i];
    const double x = v.sx(f.x);
    double y = v.sy(f.y);
    const double half_width = 3.6 * static_cast<double>(cc2.feature_ids[i].size());
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
    svg += "<text class=\"label\" x=\"" + num(x, 2) + "\" y=\"" + num(y, 2) + "\" fill=\"" + feature_colour(f.type) + "\">" +
           escape(cc2.feature_ids[i]) + "</text>\n";
  }
  svg += "</svg>\n";

  // Side panel: setup warnings first, where they cannot be missed.
  std::string panel;
  if (!in.setup_warnings.empty()) {
    panel += "<div class=\"setup\"><h2>Check the setup (" + std::to_string(in.setup_warnings.size()) +
             (in.setup_warnings.size() == 1 ? " warning" : " warnings") + ")</h2>\n<ul>\n";
    for (const auto& warning : in.setup_warnings) panel += "<li>" + escape(warning) + "</li>\n";
    panel += "</ul></div>\n";
  }
  panel += "<h2>Features (" + std::to_string(cc2.features.size()) + ")</h2>\n<table><tr><th>id</th><th>type</th><th>centre</th>"
           "<th>z top / bottom</th><th>size</th><th>operations</th></tr>\n";
  for (std::size_t i = 0; i < cc2.features.size(); ++i) {
    const auto& f = cc2.features[i];
    std::string ops;
    for (const auto& op : f.operations) {
      ops += escape(std::string(fr::to_string(op.type))) + " T" + std::to_string(op.tool_number);
      if (op.strategy != fr::Strategy::None && op.strategy != fr::Strategy::Plunge) ops += " (" + escape(std::string(fr::to_string(op.strategy))) + ")";
      ops += "<br>";
    }
    panel += "<tr data-f=\"" + std::to_string(i) + "\"><td><span class=\"sw\" style=\"border-color:" + std::string(feature_colour(f.type)) + "\"></span>" +
             escape(cc2.feature_ids[i]) + "</td><td>" + escape(std::string(fr::to_string(f.type))) + "</td><td>" + num(f.x, 2) + ", " +
             num(f.y, 2) + "</td><td>" + num(f.top_z, 2) + " / " + num(f.bottom_z, 2) + "</td><td>" + dims_text(f) + "</td><td>" + ops +
             "</td></tr>\n";
  }
  panel += "</table>\n<h2>Workingsteps (" + std::to_string(legend.size()) + ")</h2>\n<ul class=\"legend\">\n";
  for (std::size_t i = 0; i < legend.size(); ++i) {
    panel += "<li data-ws=\"" + std::to_string(i) + "\"><label><input type=\"checkbox\" checked data-ws=\"" + std::to_string(i) +
             "\"> <span class=\"sw\" style=\"background:" + std::string(kPalette[i % std::size(kPalette)]) + "\"></span>" +
             escape(legend[i]) + "</label></li>\n";
  }
  panel += "</ul>\n<h2>Tools</h2>\n<table><tr><th>id</th><th>&#8960; mm</th></tr>\n";
  for (const auto& t : project.tools) {
    panel += "<tr><td>" + escape(t.its_id) + "</td><td>" + num(t.dimension.diameter) + "</td></tr>\n";
  }
  panel += "</table>\n<h2>Warnings (" + std::to_string(in.setup_warnings.size() + in.warnings.size()) + ")</h2>\n<ul>\n";
  for (const auto& warning : in.setup_warnings) panel += "<li>" + escape(warning) + "</li>\n";
  for (const auto& warning : in.warnings) panel += "<li>" + escape(warning) + "</li>\n";
  if (in.warnings.empty() && in.setup_warnings.empty()) panel += "<li>none</li>\n";
  panel += "</ul>\n";
  if (thin > 0) panel += "<p class=\"note\">Toolpaths thinned for display (" + std::to_string(total_points) + " points).</p>\n";

  // The 3D view's data: toolpaths (x,y,z triples, thinned like the drawing), features, stock.
  double zmin = stock.min[2], zmax = stock.max[2];
  std::string data = "{\"stock\":{\"min\":[" + num(stock.min[0]) + "," + num(stock.min[1]) + "," + num(stock.min[2]) + "],\"max\":[" +
                     num(stock.max[0]) + "," + num(stock.max[1]) + "," + num(stock.max[2]) + "]},\"colours\":[";
  for (std::size_t i = 0; i < std::size(kPalette); ++i) data += std::string(i ? "," : "") + "\"" + kPalette[i] + "\"";
  data += "],\"paths\":[";
  bool first_path = true;
  for (const auto& p : paths) {
    if (p.points.empty()) continue;
    std::string pts;
    double lx = 1e300, ly = 1e300;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      const auto& q = p.points[i];
      if (thin > 0 && i + 1 < p.points.size() && std::hypot(q.x - lx, q.y - ly) < thin) continue;
      pts += (pts.empty() ? "" : ",") + num(q.x) + "," + num(q.y) + "," + num(q.z);
      lx = q.x, ly = q.y;
      zmin = std::min(zmin, q.z), zmax = std::max(zmax, q.z);
    }
    data += std::string(first_path ? "" : ",") + "{\"w\":" + std::to_string(p.workingstep) + ",\"r\":" + (p.rapid ? "1" : "0") +
            ",\"p\":[" + pts + "]}";
    first_path = false;
  }
  data += "],\"features\":[";
  bool first_feature = true;
  for (std::size_t i = 0; i < cc2.features.size(); ++i) {
    const std::string f = feature_json(cc2.features[i], cc2.feature_ids[i]);
    if (f.empty()) continue;
    data += std::string(first_feature ? "" : ",") + f.substr(0, f.size() - 1) + ",\"i\":" + std::to_string(i) + "}";
    first_feature = false;
  }
  data += "]}";
  const std::string view3d =
      "<h2>3D view <span class=\"note\">drag: turn &#183; right drag or shift drag: pan &#183; wheel: zoom &#183; mm, "
      "axes at the program zero: X red, Y green, Z blue &#183; grid 10 mm</span></h2>\n"
      "<div class=\"controls\"><button data-view=\"iso\">iso</button> <button data-view=\"top\">top</button> "
      "<button data-view=\"front\">front</button> <button data-view=\"side\">side</button> "
      "<label><input type=\"checkbox\" id=\"show-rapids\" checked> rapid moves</label> "
      "<label><input type=\"checkbox\" id=\"show-features\" checked> features</label> &#183; "
      "<label>lowest Z shown <input type=\"range\" id=\"zcut\" min=\"" + num(zmin - 0.001) + "\" max=\"" + num(zmax) +
      "\" step=\"any\" value=\"" + num(zmin - 0.001) + "\"> <output id=\"zcut-value\">all</output></label></div>\n"
      "<div id=\"view3d\"></div><p id=\"view3d-status\" class=\"note\"></p>\n"
      "<script type=\"application/json\" id=\"ncb-data\">" + data + "</script>\n";
  // At the end of the body: the views are sized once the side panel is laid out.
  const std::string scripts =
      "<script>\n" + std::string(three_js()) + "\n</script>\n<script>\n" + std::string(html_viewer_js()) + "\n</script>\n";

  std::string html;
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>ncbridge CC2: " + escape(in.title) +
          "</title>\n<style>\n"
          "body{margin:0;font:12px/1.35 system-ui,sans-serif;color:#222;display:flex;min-height:100vh}\n"
          "main{flex:1 1 auto;padding:12px;overflow:auto}\n"
          "aside{flex:0 0 560px;padding:12px 16px;border-left:1px solid #ccc;background:#fafafa;overflow:auto;max-height:100vh;box-sizing:border-box}\n"
          "h1{font-size:16px;margin:0 0 8px}h2{font-size:14px;margin:14px 0 6px}\n"
          "table{border-collapse:collapse;width:100%;table-layout:fixed}td,th{border-bottom:1px solid #e2e2e2;padding:2px 4px;"
          "text-align:left;vertical-align:top;overflow-wrap:anywhere}\n"
          "ul{padding-left:18px;margin:4px 0}.legend{list-style:none;padding:0}\n"
          ".sw{display:inline-block;width:12px;height:12px;margin-right:6px;vertical-align:middle;border:2px solid transparent;box-sizing:border-box}\n"
          "#view3d{width:100%;height:520px;border:1px solid #ccc;background:#fff}.controls{margin:4px 0}.controls button{font:inherit}\n"
          "tr[data-f]{cursor:pointer}tr.hl{background:#fff3b0}svg g.hl{stroke-width:5}svg polyline.dim{stroke-opacity:0.08}\n"
          "#top{cursor:grab}svg{max-width:100%;height:auto}svg .label{font:bold 12px system-ui,sans-serif;text-anchor:middle;dominant-baseline:middle;"
          "paint-order:stroke;stroke:#fff;stroke-width:3px}svg .axis{font:12px system-ui,sans-serif;fill:#666}\n"
          ".note{color:#666}.setup{border:2px solid #c0392b;background:#fdecea;padding:4px 10px;margin-bottom:8px}\n"
          ".setup h2{color:#c0392b;margin-top:4px}\n</style>\n</head>\n<body>\n<main>\n<h1>" +
          escape(in.title) + " &#8212; top view <span class=\"note\">wheel: zoom &#183; drag: pan &#183; double click: whole view</span></h1>\n" +
          svg + view3d + "</main>\n<aside>\n" + panel + "</aside>\n" + scripts + "</body>\n</html>\n";
  return html;
}

}  // namespace ncbridge::cli
