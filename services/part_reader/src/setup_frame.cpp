#include "ncbridge/part_reader/setup_frame.hpp"

#include <cmath>
#include <cstdio>

namespace ncbridge::part_reader {

namespace {

// Rotations (row-major) that bring each side to +Z.
std::array<double, 9> turn_for(SetupUp up) {
  switch (up) {
    case SetupUp::PlusZ: return {1, 0, 0, 0, 1, 0, 0, 0, 1};
    case SetupUp::MinusZ: return {1, 0, 0, 0, -1, 0, 0, 0, -1};  // half a turn about X
    case SetupUp::PlusX: return {0, 0, -1, 0, 1, 0, 1, 0, 0};    // a quarter turn about Y
    case SetupUp::MinusX: return {0, 0, 1, 0, 1, 0, -1, 0, 0};
    case SetupUp::PlusY: return {1, 0, 0, 0, 0, -1, 0, 1, 0};    // a quarter turn about X
    case SetupUp::MinusY: return {1, 0, 0, 0, 0, 1, 0, -1, 0};
  }
  return {1, 0, 0, 0, 1, 0, 0, 0, 1};
}

double clean(double v) { return std::abs(v) < 1e-12 ? 0.0 : v; }

}  // namespace

SetupFrame::SetupFrame(const ReadOptions& options) : up_(options.up), r_(turn_for(options.up)), t_(options.offset) {}

stepnc::CartesianPoint SetupFrame::point(const stepnc::CartesianPoint& p) const {
  return {clean(r_[0] * p.x + r_[1] * p.y + r_[2] * p.z + t_[0]), clean(r_[3] * p.x + r_[4] * p.y + r_[5] * p.z + t_[1]),
          clean(r_[6] * p.x + r_[7] * p.y + r_[8] * p.z + t_[2])};
}

stepnc::Direction SetupFrame::direction(const stepnc::Direction& d) const {
  return {clean(r_[0] * d.x + r_[1] * d.y + r_[2] * d.z), clean(r_[3] * d.x + r_[4] * d.y + r_[5] * d.z),
          clean(r_[6] * d.x + r_[7] * d.y + r_[8] * d.z)};
}

stepnc::Direction SetupFrame::to_part(const stepnc::Direction& d) const {
  return {clean(r_[0] * d.x + r_[3] * d.y + r_[6] * d.z), clean(r_[1] * d.x + r_[4] * d.y + r_[7] * d.z),
          clean(r_[2] * d.x + r_[5] * d.y + r_[8] * d.z)};
}

stepnc::Axis2Placement3d SetupFrame::placement(const stepnc::Axis2Placement3d& p) const {
  return {point(p.location), direction(p.axis), direction(p.ref_direction)};
}

void move_part(Part& part, const std::array<double, 3>& offset) {
  auto move = [&](stepnc::CartesianPoint& p) {
    p.x += offset[0];
    p.y += offset[1];
    p.z += offset[2];
  };
  for (auto& f : part.features) move(f.placement.location);
  if (part.stock) move(part.stock->placement.location);
  for (auto& v : part.footprint) {
    v.x += offset[0];
    v.y += offset[1];
  }
  part.top_z += offset[2];
  part.bottom_z += offset[2];
  if (part.bounds) {
    for (int i = 0; i < 3; ++i) {
      part.bounds->min[static_cast<std::size_t>(i)] += offset[static_cast<std::size_t>(i)];
      part.bounds->max[static_cast<std::size_t>(i)] += offset[static_cast<std::size_t>(i)];
    }
  }
}

std::optional<SetupUp> setup_facing(const stepnc::Direction& d) {
  const double n = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (n == 0) return std::nullopt;
  const double x = d.x / n, y = d.y / n, z = d.z / n;
  constexpr double tol = 1e-6;
  if (std::abs(z - 1) < tol) return SetupUp::PlusZ;
  if (std::abs(z + 1) < tol) return SetupUp::MinusZ;
  if (std::abs(x - 1) < tol) return SetupUp::PlusX;
  if (std::abs(x + 1) < tol) return SetupUp::MinusX;
  if (std::abs(y - 1) < tol) return SetupUp::PlusY;
  if (std::abs(y + 1) < tol) return SetupUp::MinusY;
  return std::nullopt;
}

std::string direction_text(const stepnc::Direction& d) {
  auto f = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", std::abs(v) < 5e-7 ? 0.0 : std::round(v * 1e6) / 1e6);
    return std::string(buf);
  };
  std::string text = "(";
  text += f(d.x);
  text += ", ";
  text += f(d.y);
  text += ", ";
  text += f(d.z);
  text += ")";
  return text;
}

std::string needed_setup_text(const stepnc::Direction& part_axis) {
  std::string text = "axis " + direction_text(part_axis) + " in the part frame: ";
  if (const auto up = setup_facing(part_axis)) {
    const std::string name(to_string(*up));
    return text + "needs a setup with " + name + " up (--setup " + name + ")";
  }
  return text + "needs a tilted setup (5-axis or a fixture at an angle)";
}

}  // namespace ncbridge::part_reader
