#include "optimize_html.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string_view>

#include "errors.hpp"
#include "html_text.hpp"

namespace ncbridge::cli {

namespace to = toolpath_optimizer;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kPanelPx = 640;            // each drawing's width
constexpr std::size_t kMaxDots = 40000;     // vertex dots drawn at most per side

std::string escape(std::string_view s) { return html_escape(s); }

std::string num(double v, int decimals = 3) { return short_number(v, decimals); }

// The layer a motion lies in: its Z in 0.01 mm steps, when it stays at that Z and moves in XY.
std::optional<long> layer_key(const to::PathPiece& p) {
  if (std::abs(p.start.z - p.end.z) > 0.001) return std::nullopt;
  if (p.kind != to::MotionKind::Arc && std::hypot(p.end.x - p.start.x, p.end.y - p.start.y) < 1e-6) return std::nullopt;
  if (p.kind == to::MotionKind::Arc && p.arc.plane != canonical::Plane::XY) return std::nullopt;
  return std::lround(p.start.z * 100);
}

// An arc's points in XY (the plane XY only: see layer_key), at most 5 degrees apart.
std::vector<to::Vec3> arc_points(const to::PathPiece& p) {
  const double cx = p.arc.first_centre, cy = p.arc.second_centre;
  const double a0 = std::atan2(p.start.y - cy, p.start.x - cx), a1 = std::atan2(p.end.y - cy, p.end.x - cx);
  const double r = std::hypot(p.start.x - cx, p.start.y - cy);
  double sweep = p.arc.ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-9) sweep += 2 * kPi;
  sweep += 2 * kPi * p.arc.extra_turns;
  const int steps = std::max(2, static_cast<int>(std::ceil(sweep / (5 * kPi / 180))));
  std::vector<to::Vec3> out;
  for (int k = 0; k <= steps; ++k) {
    const double a = a0 + (p.arc.ccw ? 1 : -1) * sweep * k / steps;
    out.push_back({cx + r * std::cos(a), cy + r * std::sin(a), p.start.z + (p.end.z - p.start.z) * k / steps});
  }
  out.back() = p.end;
  return out;
}

// A move that cuts nothing: a rapid, or on a printer a move that extrudes nothing.
bool is_travel(const to::PathPiece& p, bool printer) {
  return p.kind == to::MotionKind::Traverse || (printer && p.extrusion <= 1e-9);
}

struct LayerCounts {
  long key = 0;
  std::size_t before_cuts = 0, before_arcs = 0, after_lines = 0, after_arcs = 0;
};

struct Frame {
  double xmin, ymax, scale, margin = 20;
  std::string pt(double x, double y) const {
    return num(margin + (x - xmin) * scale, 2) + "," + num(margin + (ymax - y) * scale, 2);
  }
};

// One side's drawing of the layer: runs of joined lines as polylines, arcs each its own, rapid
// moves dashed, the motions' ends as dots.
std::string side_svg(const std::vector<const to::PathPiece*>& pieces, const Frame& f, double width, double height, const char* id,
                     const char* line_colour, bool arcs_apart, bool printer, std::size_t& dots) {
  std::string svg = "<svg id=\"" + std::string(id) + "\" class=\"layer\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + num(width, 0) + " " +
                    num(height, 0) + "\" width=\"" + num(width, 0) + "\" height=\"" + num(height, 0) + "\">\n<g fill=\"none\" stroke-linejoin=\"round\">\n";
  std::string run;
  const to::PathPiece* last = nullptr;
  auto flush = [&] {
    if (!run.empty()) svg += "<polyline class=\"ln\" points=\"" + run + "\" stroke=\"" + line_colour + "\" stroke-width=\"1.3\"/>\n";
    run.clear();
  };
  std::string ends;
  dots = 0;
  auto dot = [&](const to::Vec3& p) {
    if (dots >= kMaxDots) return;
    const std::string q = f.pt(p.x, p.y);
    const auto comma = q.find(',');
    ends += "<circle cx=\"" + q.substr(0, comma) + "\" cy=\"" + q.substr(comma + 1) + "\" r=\"1.6\"/>";
    ++dots;
  };
  for (const auto* p : pieces) {
    if (is_travel(*p, printer)) {
      flush();
      svg += "<polyline class=\"rp\" points=\"" + f.pt(p->start.x, p->start.y) + " " + f.pt(p->end.x, p->end.y) +
             "\" stroke=\"#999\" stroke-width=\"0.8\" stroke-dasharray=\"4 3\"/>\n";
      last = nullptr;
      continue;
    }
    const bool joined = last && std::abs(last->end.x - p->start.x) < 1e-9 && std::abs(last->end.y - p->start.y) < 1e-9;
    if (p->kind == to::MotionKind::Arc && arcs_apart) {
      flush();
      std::string pts;
      for (const auto& q : arc_points(*p)) pts += f.pt(q.x, q.y) + " ";
      svg += "<polyline class=\"arc\" points=\"" + pts + "\" stroke=\"#d62728\" stroke-width=\"1.8\"/>\n";
      dot(p->start);
      dot(p->end);
      last = nullptr;  // the next line run starts at this arc's end
      continue;
    }
    if (!joined) {
      flush();
      run = f.pt(p->start.x, p->start.y) + " ";
      dot(p->start);
    }
    if (p->kind == to::MotionKind::Arc) {
      const auto points = arc_points(*p);
      for (std::size_t k = 1; k < points.size(); ++k) run += f.pt(points[k].x, points[k].y) + " ";
    } else {
      run += f.pt(p->end.x, p->end.y) + " ";
    }
    dot(p->end);
    last = p;
  }
  flush();
  svg += "</g>\n<g class=\"ends\" fill=\"#222\">" + ends + "</g>\n</svg>\n";
  return svg;
}

const char* const kScript = R"JS(
(function () {
  'use strict';
  if (location.hash === '#picture') document.body.classList.add('picture');  // the drawings alone (docs)
  // Both drawings share one view box: wheel zoom about the pointer, drag to pan, double click
  // for the whole layer; the dots keep their size on the screen.
  var svgs = Array.prototype.slice.call(document.querySelectorAll('svg.layer'));
  var whole = svgs[0].getAttribute('viewBox').split(' ').map(Number);
  var box = whole.slice();
  var scale = Number(document.body.dataset.scale);
  function set() {
    svgs.forEach(function (s) {
      s.setAttribute('viewBox', box.join(' '));
      Array.prototype.forEach.call(s.querySelectorAll('circle'), function (c) { c.setAttribute('r', 1.6 * box[2] / whole[2]); });
    });
    var r = svgs[0].getBoundingClientRect();
    var pxPerMm = r.width / box[2] * scale, target = 100 / pxPerMm, p = Math.pow(10, Math.floor(Math.log10(target))), mm = p;
    [1, 2, 5, 10].forEach(function (k) { if (k * p <= target) mm = k * p; });
    Array.prototype.forEach.call(document.querySelectorAll('.scalebar'), function (bar) {
      bar.firstChild.style.width = (mm * pxPerMm) + 'px';
      bar.lastChild.textContent = (mm >= 1 ? mm : mm.toPrecision(1)) + ' mm';
    });
  }
  function at(s, e) {
    var r = s.getBoundingClientRect();
    return [box[0] + (e.clientX - r.left) / r.width * box[2], box[1] + (e.clientY - r.top) / r.height * box[3]];
  }
  var drag = null;
  svgs.forEach(function (s) {
    s.addEventListener('wheel', function (e) {
      e.preventDefault();
      var p = at(s, e), k = e.deltaY < 0 ? 0.8 : 1.25;
      box = [p[0] - (p[0] - box[0]) * k, p[1] - (p[1] - box[1]) * k, box[2] * k, box[3] * k];
      set();
    }, {passive: false});
    s.addEventListener('mousedown', function (e) { drag = [s, at(s, e)]; });
    s.addEventListener('mousemove', function (e) {
      if (!drag || drag[0] !== s) return;
      var p = at(s, e);
      box[0] -= p[0] - drag[1][0];
      box[1] -= p[1] - drag[1][1];
      set();
    });
    s.addEventListener('dblclick', function () { box = whole.slice(); set(); });
  });
  window.addEventListener('mouseup', function () { drag = null; });
  window.addEventListener('resize', set);
  set();
  function count(id, selector) { return document.querySelectorAll('#' + id + ' ' + selector).length; }
  document.body.dataset.drawn = JSON.stringify({
    before_runs: count('before', 'polyline.ln'), before_dots: count('before', 'circle'),
    after_runs: count('after', 'polyline.ln'), after_arcs: count('after', 'polyline.arc'), after_dots: count('after', 'circle')});
})();
)JS";

}  // namespace

static std::string count(std::size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

std::string optimize_html(const OptimizeHtmlInput& in) {
  const auto& before = *in.before;
  const auto& after = *in.after;
  // The layers, in the order the input reaches them.
  std::vector<LayerCounts> layers;
  std::map<long, std::size_t> index;
  for (const auto& p : before) {
    const auto key = layer_key(p);
    if (!key || is_travel(p, in.printer)) continue;
    auto [it, added] = index.emplace(*key, layers.size());
    if (added) layers.push_back({*key});
    auto& l = layers[it->second];
    ++l.before_cuts;
    l.before_arcs += p.kind == to::MotionKind::Arc;
  }
  for (const auto& p : after) {
    const auto key = layer_key(p);
    if (!key || is_travel(p, in.printer)) continue;
    const auto it = index.find(*key);
    if (it == index.end()) continue;
    auto& l = layers[it->second];
    (p.kind == to::MotionKind::Arc ? l.after_arcs : l.after_lines) += 1;
  }
  if (layers.empty()) throw UsageError("--html: the program has no motion in a plane of constant Z to draw");
  std::size_t chosen = (layers.size() - 1) / 2;
  if (in.layer) {
    if (*in.layer < 1 || *in.layer > layers.size()) {
      throw UsageError("--html-layer " + std::to_string(*in.layer) + ": the program has " + std::to_string(layers.size()) +
                       (layers.size() == 1 ? " layer" : " layers") + " (1 to " + std::to_string(layers.size()) + ")");
    }
    chosen = *in.layer - 1;
  } else if (in.z) {
    const auto it = index.find(std::lround(*in.z * 100));
    if (it == index.end()) {
      std::string near;
      double best = 1e300;
      for (const auto& l : layers) {
        if (std::abs(l.key / 100.0 - *in.z) < best) best = std::abs(l.key / 100.0 - *in.z), near = num(l.key / 100.0, 2);
      }
      throw UsageError("--html-z " + num(*in.z) + ": no layer at that Z (the nearest is Z " + near + ")");
    }
    chosen = it->second;
  }
  const long key = layers[chosen].key;
  const double z = key / 100.0;
  auto in_layer = [&](const to::PathPiece& p) {
    if (is_travel(p, in.printer)) return std::lround(p.start.z * 100) == key && std::lround(p.end.z * 100) == key;
    const auto k = layer_key(p);
    return k && *k == key;
  };
  std::vector<const to::PathPiece*> b, a;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  auto extend = [&](const to::PathPiece& p) {
    std::vector<to::Vec3> points{p.start, p.end};
    if (p.kind == to::MotionKind::Arc) points = arc_points(p);
    for (const auto& q : points) xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x), ymin = std::min(ymin, q.y), ymax = std::max(ymax, q.y);
  };
  for (const auto& p : before) {
    if (in_layer(p)) b.push_back(&p), extend(p);
  }
  for (const auto& p : after) {
    if (in_layer(p)) a.push_back(&p), extend(p);
  }
  const double w = std::max(xmax - xmin, 1e-3), h = std::max(ymax - ymin, 1e-3);
  Frame f{xmin, ymax, kPanelPx / std::max(w, h)};
  const double width = w * f.scale + 2 * f.margin, height = h * f.scale + 2 * f.margin;
  std::size_t before_dots = 0, after_dots = 0;
  const std::string before_svg = side_svg(b, f, width, height, "before", "#1f77b4", false, in.printer, before_dots);
  const std::string after_svg = side_svg(a, f, width, height, "after", "#2ca02c", true, in.printer, after_dots);
  const LayerCounts& c = layers[chosen];

  const auto& r = *in.result;
  std::string stats = "<table class=\"stats\"><tr><th></th><th>before</th><th>after</th></tr>"
                      "<tr><td>this layer: motions</td><td>" + std::to_string(c.before_cuts) + (c.before_arcs ? " (" + std::to_string(c.before_arcs) + " arcs)" : "") +
                      "</td><td>" + std::to_string(c.after_lines + c.after_arcs) + ": " + std::to_string(c.after_lines) + " lines, " +
                      std::to_string(c.after_arcs) + " arcs</td></tr>"
                      "<tr><td>the program: motion blocks</td><td>" + std::to_string(r.motion_blocks_in) + "</td><td>" + std::to_string(r.motion_blocks_out) + "</td></tr>"
                      "<tr><td>the program: commands</td><td>" + std::to_string(r.commands_in) + "</td><td>" + std::to_string(r.commands_out) + "</td></tr>"
                      "<tr><td>arcs made, lines merged, loops</td><td></td><td>" + std::to_string(r.stats.arcs) + ", " + std::to_string(r.stats.lines_merged) + ", " +
                      std::to_string(r.loops.loops) + "</td></tr>";
  if (r.deviation) {
    stats += "<tr><td>largest deviation (band " + num(in.tolerance, 4) + " mm)</td><td colspan=\"2\">" + num(r.deviation->largest(), 4) + " mm</td></tr>";
  }
  stats += "</table>\n";
  std::string table = "<table class=\"layers\"><tr><th>layer</th><th>Z mm</th><th>motions before</th><th>lines after</th><th>arcs after</th></tr>\n";
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const auto& l = layers[i];
    table += std::string("<tr") + (i == chosen ? " class=\"chosen\"" : "") + "><td>" + std::to_string(i + 1) + "</td><td>" + num(l.key / 100.0, 2) +
             "</td><td>" + std::to_string(l.before_cuts) + "</td><td>" + std::to_string(l.after_lines) + "</td><td>" + std::to_string(l.after_arcs) + "</td></tr>\n";
  }
  table += "</table>\n";

  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>ncbridge optimize: " + escape(in.program) +
                     "</title>\n<style>\n"
                     "body{margin:12px;font:12px/1.35 system-ui,sans-serif;color:#222}h1{font-size:16px;margin:0 0 6px}h2{font-size:14px;margin:12px 0 4px}\n"
                     ".sides{display:flex;gap:12px;flex-wrap:wrap}.side{flex:1 1 480px;min-width:0}\n"
                     ".frame{position:relative;border:1px solid #ccc;background:#fff}svg.layer{display:block;width:100%;height:auto;cursor:grab}\n"
                     "svg.layer polyline{vector-effect:non-scaling-stroke}\n"
                     ".scalebar{position:absolute;right:10px;bottom:8px;font:11px system-ui,sans-serif;background:rgba(255,255,255,.85);padding:2px 4px}\n"
                     ".scalebar div{height:5px;border:1.5px solid #222;border-top:none}\n"
                     "table{border-collapse:collapse}td,th{border-bottom:1px solid #e2e2e2;padding:2px 8px;text-align:left}tr.chosen{background:#fff3b0}\n"
                     ".key span{display:inline-block;width:22px;height:0;vertical-align:middle;margin:0 4px 0 12px;border-top:2px solid}\n"
                     ".note{color:#666}body.picture .tables,body.picture h1 .note{display:none}\n</style>\n</head>\n<body data-scale=\"" + num(f.scale, 6) + "\" data-layer=\"" + std::to_string(chosen + 1) +
                     "\" data-layer-counts=\"" + std::to_string(c.before_cuts) + " " + std::to_string(c.after_lines) + " " + std::to_string(c.after_arcs) + "\">\n"
                     "<h1>" + escape(in.program) + " &#8594; " + escape(in.output) + ": layer " + std::to_string(chosen + 1) + " of " + std::to_string(layers.size()) +
                     ", Z " + num(z, 2) + " mm <span class=\"note\">mm, top view &#183; wheel: zoom &#183; drag: pan &#183; double click: whole layer &#183; "
                     "another layer: --html-layer N or --html-z Z</span></h1>\n"
                     "<p class=\"key\"><span style=\"border-color:#1f77b4\"></span>input motions<span style=\"border-color:#2ca02c\"></span>output lines"
                     "<span style=\"border-color:#d62728\"></span>output arcs<span style=\"border-top:1px dashed #999\"></span>" + std::string(in.printer ? "travel (no extrusion)" : "rapid moves") + " &#183; dots: the ends of each motion"
                     "</p>\n<div class=\"sides\"><div class=\"side\"><h2>Before: " + std::to_string(c.before_cuts) + " motions</h2><div class=\"frame\">" + before_svg +
                     "<div class=\"scalebar\"><div></div><span></span></div></div></div>\n<div class=\"side\"><h2>After: " +
                     count(c.after_lines, "line", "lines") + " and " + count(c.after_arcs, "arc", "arcs") + "</h2><div class=\"frame\">" + after_svg +
                     "<div class=\"scalebar\"><div></div><span></span></div></div></div></div>\n";
  if (before_dots >= kMaxDots || after_dots >= kMaxDots) html += "<p class=\"note\">Only the first " + std::to_string(kMaxDots) + " ends are dotted.</p>\n";
  html += "<div class=\"tables\"><h2>Counts</h2>\n" + stats + "<h2>Layers</h2>\n" + table + "</div><script>" + kScript + "</script>\n</body>\n</html>\n";
  return html;
}

}  // namespace ncbridge::cli
