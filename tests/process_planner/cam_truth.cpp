#include "cam_truth.hpp"

#include <cmath>
#include <numbers>

namespace ncbridge::testing {

namespace {

constexpr double kCentre = 0.05, kSize = 0.05, kExact = 1e-6;

// The extents along x and y of a report feature's rectangle (its length at angle_deg).
std::pair<double, double> extents(const nlohmann::json& dims) {
  const double a = dims.value("angle_deg", 0.0) * std::numbers::pi / 180;
  const double l = dims.value("length", 0.0), w = dims.value("width", 0.0);
  return {std::abs(l * std::cos(a)) + std::abs(w * std::sin(a)), std::abs(l * std::sin(a)) + std::abs(w * std::cos(a))};
}

bool near(double a, double b, double tol) { return std::abs(a - b) <= tol; }

// Why the report feature is not the truth feature ("" when it is).
std::string mismatch(const nlohmann::json& r, const nlohmann::json& t) {
  const std::string type = t["type"];
  if (r["type"] != type) return "type";
  const auto& pos = t["position"];
  if (std::hypot(r["center_xy"][0].get<double>() - pos[0].get<double>(), r["center_xy"][1].get<double>() - pos[1].get<double>()) > kCentre) {
    return "centre";
  }
  if (!near(r["top_z"], t["top_z"], kExact) || !near(r["bottom_z"], t["bottom_z"], kExact)) return "top/bottom";
  const auto& td = t["dimensions"];
  const auto& rd = r["dimensions"];
  if (type == "round_hole") return near(rd["diameter"], td["diameter"], kSize) ? "" : "diameter";
  if (type == "planar_face" || type == "general_outside_profile") {
    const auto [x, y] = extents(rd);
    return near(x, td["length_x"], kSize) && near(y, td["width_y"], kSize) ? "" : "size";
  }
  if (type == "closed_pocket") {
    if (td.contains("diameter")) return rd.contains("diameter") && near(rd["diameter"], td["diameter"], kSize) ? "" : "diameter";
    if (!near(rd["length"], td["length"], kSize) || !near(rd["width"], td["width"], kSize)) return "size";
    if (!near(rd.value("corner_radius", 0.0), td["corner_radius"], kSize)) return "corner radius";
    const double da = std::fmod(std::abs(rd["angle_deg"].get<double>() - td["angle_deg"].get<double>()), 180.0);
    return std::min(da, 180 - da) <= 0.01 ? "" : "angle";
  }
  if (type == "slot") {
    const double length = td.contains("length") ? td["length"].get<double>() : td["length_overall"].get<double>();
    return near(rd["width"], td["width"], kSize) && near(rd["length"], length, kSize) ? "" : "size";
  }
  if (type == "step") return near(rd["length"], td["length"], kSize) && near(rd["width"], td["width"], kSize) ? "" : "size";
  if (type == "open_pocket") {
    const auto& region = t["region_xy"];
    const auto [x, y] = extents(rd);
    return near(x, region[2].get<double>() - region[0].get<double>(), kSize) && near(y, region[3].get<double>() - region[1].get<double>(), kSize)
               ? ""
               : "size";
  }
  return "unknown type";
}

}  // namespace

TruthScore score_against_truth(const nlohmann::json& report, const nlohmann::json& truth) {
  TruthScore s;
  s.truth = static_cast<int>(truth.size());
  s.reported = static_cast<int>(report.size());
  std::vector<char> used(report.size(), 0);
  for (const auto& t : truth) {
    std::string nearest = "no " + t["type"].get<std::string>();
    bool found = false;
    for (std::size_t i = 0; i < report.size() && !found; ++i) {
      if (used[i]) continue;
      const std::string why = mismatch(report[i], t);
      if (why.empty()) {
        used[i] = 1;
        found = true;
      } else if (why != "type") {
        nearest = report[i]["id"].get<std::string>() + ": " + why;
      }
    }
    if (found) ++s.matched;
    else s.unmatched.push_back(t["id"].get<std::string>() + " (" + nearest + ")");
  }
  return s;
}

}  // namespace ncbridge::testing
