#include "siemens840d/pocket_milling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace ncbridge::interpreter::siemens840d {

using lowering::DialectMachine;
using lowering::NeutralBlock;
using lowering::Point3;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// What both pockets share: parameters, feeds, layers, direction and the moves themselves.
class PocketCut {
 public:
  PocketCut(DialectMachine& m, const std::string& name, const std::map<std::string, double>& args, double tool_radius,
            std::uint32_t column)
      : m_(m), name_(name), args_(args), column_(column), tool_radius_(tool_radius) {
    rtp_ = get("RTP");
    rfp_ = get("RFP", 0.0);
    sdis_ = std::fabs(get("SDIS", 0.0));
    depth_ = get("DP");
    const int vari = static_cast<int>(std::lround(get("VARI", 1.0)));
    if (vari % 10 != 1 && vari % 10 != 2) fail("VARI units digit must be 1 (roughing) or 2 (finishing)");
    if (vari / 10 != 0) {
      fail("helical or oscillating infeed (VARI tens digit " + std::to_string(vari / 10) +
           ") is not supported: only vertical infeed (VARI=1 or 2)");
    }
    finishing_ = vari % 10 == 2;
    allowance_ = finishing_ ? 0.0 : std::fabs(get("FAL", 0.0));
    base_allowance_ = finishing_ ? 0.0 : std::fabs(get("FALD", 0.0));
    plane_feed_ = get("FFP1", 0.0);
    depth_feed_ = get("FFD", 0.0);
    if (plane_feed_ <= 0) fail("FFP1 (the feed in the plane) must be positive");
    if (depth_feed_ <= 0) fail("FFD (the infeed feed) must be positive");
    if (tool_radius_ <= 0) fail("needs the tool's diameter: the tool in the spindle has none in the tool list");
    const double mida = std::fabs(get("MIDA", 0.0));
    step_ = mida > 0 ? mida : 1.6 * tool_radius_;
    const int cdir = static_cast<int>(std::lround(get("CDIR", 0.0)));
    if (cdir < 0 || cdir > 3) fail("CDIR must be 0 (climb), 1 (conventional), 2 (G2) or 3 (G3)");
    const bool spindle_cw = m_.state().spindle != canonical::Direction::Counterclockwise;
    // inside a pocket, climb milling with a clockwise spindle runs counter-clockwise
    ccw_ = cdir == 3 || (cdir == 0 && spindle_cw) || (cdir == 1 && !spindle_cw);
    if (depth_ + base_allowance_ >= rfp_) fail("the pocket depth DP is not below the reference plane RFP");
    if (rtp_ < rfp_ + sdis_) fail("the retraction plane RTP is below RFP + SDIS");
  }

  double get(const char* p, std::optional<double> fallback = std::nullopt) const {
    auto it = args_.find(p);
    if (it != args_.end()) return it->second;
    if (fallback) return *fallback;
    fail(std::string("parameter _") + p + " missing");
  }
  [[noreturn]] void fail(const std::string& what) const { m_.fail(column_, name_ + ": " + what); }

  // Layers times rings within the interpreter's iteration limit (a tiny MID or MIDA is an error,
  // not hours of moves).
  void check_passes(std::size_t layers, std::size_t rings) const {
    const double passes = static_cast<double>(layers) * static_cast<double>(rings);
    if (passes > static_cast<double>(m_.options().max_loop_iterations)) {
      fail("MID/MIDA ask for " + std::to_string(static_cast<long long>(passes)) +
           " passes, more than the iteration limit (" + std::to_string(m_.options().max_loop_iterations) + ")");
    }
  }
  double tool_radius() const { return tool_radius_; }
  double allowance() const { return allowance_; }
  double step() const { return step_; }
  bool ccw() const { return ccw_; }

  // The infeed levels: equal steps of at most MID from RFP down to DP (+ FALD when roughing).
  std::vector<double> layers() const {
    const double bottom = depth_ + base_allowance_;
    const double mid = std::fabs(get("MID", 0.0));
    const double total = rfp_ - bottom;
    int n = mid > 0 ? static_cast<int>(std::ceil(total / mid - 1e-9)) : 1;
    n = std::max(n, 1);
    if (!(total / std::max(mid, 1e-300) < 1e6) && mid > 0) fail("MID too small: more than a million layers");
    std::vector<double> out;
    for (int k = 1; k <= n; ++k) out.push_back(rfp_ - total * k / n);
    return out;
  }

  void rapid(std::optional<double> x, std::optional<double> y, std::optional<double> z) {
    NeutralBlock nb;
    nb.g(0, column_);
    m_.put_axes(nb, x, y, z, column_);
    run(nb);
  }
  void feed(std::optional<double> x, std::optional<double> y, std::optional<double> z, double f) {
    NeutralBlock nb;
    nb.g(1, column_);
    nb.add('f', f, column_);
    m_.put_axes(nb, x, y, z, column_);
    run(nb);
  }
  void arc(bool ccw, double x, double y, double cx, double cy) {
    NeutralBlock nb;
    nb.add('f', plane_feed_, column_);
    m_.put_xy_arc(nb, !ccw, x, y, std::nullopt, cx, cy, column_);
    run(nb);
  }
  void line(double x, double y) {
    const Point3 here = m_.position();
    if (std::hypot(x - here.x, y - here.y) < 1e-9) return;
    feed(x, y, std::nullopt, plane_feed_);
  }
  // to RTP, over the plunge point, down to the safety clearance
  void approach(double x, double y) {
    if (std::fabs(m_.position().z - rtp_) > 1e-9) rapid(std::nullopt, std::nullopt, rtp_);
    rapid(x, y, std::nullopt);
    rapid(std::nullopt, std::nullopt, rfp_ + sdis_);
  }
  void plunge(double z) { feed(std::nullopt, std::nullopt, z, depth_feed_); }
  void leave() {
    rapid(std::nullopt, std::nullopt, rfp_ + sdis_);
    rapid(std::nullopt, std::nullopt, rtp_);
  }

 private:
  void run(const NeutralBlock& nb) {
    if (m_.execute(nb)) fail("the cycle ended the program");
  }
  DialectMachine& m_;
  std::string name_;
  const std::map<std::string, double>& args_;
  std::uint32_t column_;
  double tool_radius_;
  double rtp_ = 0, rfp_ = 0, sdis_ = 0, depth_ = 0;
  bool finishing_ = false;
  double allowance_ = 0, base_allowance_ = 0;
  double plane_feed_ = 0, depth_feed_ = 0;
  double step_ = 0;
  bool ccw_ = true;
};

// Insets of the rings from the innermost (`widest`, where the ring closes to a line or a point)
// out to the final contour (0), at most `step` apart.
std::vector<double> ring_insets(double widest, double step) {
  const double count = std::ceil(widest / step - 1e-9);
  if (!(count < 1e6)) return {};  // the caller's pass check refuses it
  const int n = std::max(1, static_cast<int>(count));
  std::vector<double> out;
  for (int k = n; k >= 0; --k) out.push_back(widest * k / n);
  return out;
}

}  // namespace

void rectangular_pocket(DialectMachine& m, const std::string& name, const std::map<std::string, double>& args,
                        double tool_radius, std::uint32_t column) {
  PocketCut cut(m, name, args, tool_radius, column);
  const double length = cut.get("LENG"), width = cut.get("WID");
  if (length <= 0 || width <= 0) {
    cut.fail("_LENG and _WID must be positive: a pocket dimensioned from a corner (signed) is not supported");
  }
  const double a = length / 2 - tool_radius - cut.allowance();
  const double b = width / 2 - tool_radius - cut.allowance();
  if (a < 0 || b < 0) cut.fail("the tool (with the allowance _FAL) is wider than the pocket");
  const double corner = std::max(0.0, cut.get("CRAD", 0.0) - tool_radius - cut.allowance());
  const double cx = cut.get("PA"), cy = cut.get("PO");
  const double angle = cut.get("STA", 0.0) * kDeg;
  const double ca = std::cos(angle), sa = std::sin(angle);
  auto at = [&](double u, double v) { return Point3{cx + ca * u - sa * v, cy + sa * u + ca * v, 0}; };
  const double widest = std::min(a, b);
  const std::vector<double> insets = ring_insets(widest, cut.step());
  const std::vector<double> layers = cut.layers();
  cut.check_passes(layers.size(), insets.empty() ? std::size_t{1} << 40 : insets.size());
  const Point3 start = at(a - widest, 0);
  cut.approach(start.x, start.y);
  const bool ccw = cut.ccw();
  for (double z : layers) {
    cut.plunge(z);
    for (double d : insets) {
      const double A = a - d, B = b - d, r = std::min(std::max(0.0, corner - d), std::min(A, B));
      const Point3 s = at(A, 0);
      cut.line(s.x, s.y);
      // the ring from (A, 0) around the rounded rectangle, counter-clockwise in the pocket's axes
      struct Corner { double u, v; int su, sv; };  // corner centre direction
      const Corner corners[4] = {{A, B, 1, 1}, {-A, B, -1, 1}, {-A, -B, -1, -1}, {A, -B, 1, -1}};
      auto ring_point = [&](int i, bool before) {  // the tangent points of corner i, in travel order
        const Corner& c = corners[i];
        // counter-clockwise: corner 0 is reached going +v and left going -u, and so on
        const double pu = c.u - c.su * r, pv = c.v - c.sv * r;
        const bool vertical_in = (i % 2 == 0) == ccw;  // arriving along a side parallel to v
        if (before == vertical_in) return std::pair<double, double>{c.u, pv};
        return std::pair<double, double>{pu, c.v};
      };
      const int order_ccw[4] = {0, 1, 2, 3}, order_cw[4] = {3, 2, 1, 0};
      const int* order = ccw ? order_ccw : order_cw;
      for (int k = 0; k < 4; ++k) {
        const int i = order[k];
        const Corner& c = corners[i];
        auto [u1, v1] = ring_point(i, true);
        auto [u2, v2] = ring_point(i, false);
        const Point3 p1 = at(u1, v1), p2 = at(u2, v2);
        cut.line(p1.x, p1.y);
        if (r > 1e-9) {
          const Point3 centre = at(c.u - c.su * r, c.v - c.sv * r);
          cut.arc(ccw, p2.x, p2.y, centre.x, centre.y);
        }
      }
      cut.line(s.x, s.y);
    }
    cut.line(start.x, start.y);
  }
  cut.leave();
}

void circular_pocket(DialectMachine& m, const std::string& name, const std::map<std::string, double>& args,
                     double tool_radius, std::uint32_t column) {
  PocketCut cut(m, name, args, tool_radius, column);
  const double radius = cut.get("PRAD") - tool_radius - cut.allowance();
  if (radius <= 0) cut.fail("the tool (with the allowance _FAL) is wider than the pocket");
  const double cx = cut.get("PA"), cy = cut.get("PO");
  std::vector<double> insets = ring_insets(radius, cut.step());
  const std::vector<double> layers = cut.layers();
  cut.check_passes(layers.size(), insets.empty() ? std::size_t{1} << 40 : insets.size());
  insets.erase(insets.begin());  // the innermost "ring" is the centre itself
  cut.approach(cx, cy);
  for (double z : layers) {
    cut.plunge(z);
    for (double d : insets) {
      cut.line(cx + radius - d, cy);
      cut.arc(cut.ccw(), cx + radius - d, cy, cx, cy);
    }
    cut.line(cx, cy);
  }
  cut.leave();
}

}  // namespace ncbridge::interpreter::siemens840d
