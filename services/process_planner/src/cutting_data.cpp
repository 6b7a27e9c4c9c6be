#include "cutting_data.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncbridge::process_planner {

namespace {

// Cutting speed (m/min) and feed (mm per tooth for milling, mm per revolution for drilling) at a
// diameter of 10 mm, for carbide tools.
struct MaterialData {
  double milling_speed, feed_per_tooth, drilling_speed, feed_per_rev;
};

MaterialData data_of(Material m) {
  switch (m) {
    case Material::Steel: return {120, 0.04, 70, 0.15};
    case Material::Aluminium: return {400, 0.06, 150, 0.25};
    case Material::StainlessSteel: return {80, 0.03, 45, 0.10};
    case Material::CastIron: return {100, 0.05, 70, 0.20};
    case Material::Brass: return {200, 0.05, 100, 0.20};
    case Material::Plastic: return {250, 0.08, 100, 0.20};
  }
  return {120, 0.04, 70, 0.15};
}

int teeth_of(const setup::Tool& t) {
  if (t.flutes > 0) return t.flutes;
  switch (t.type) {
    case setup::ToolType::FaceMill: return 4;
    case setup::ToolType::Drill: case setup::ToolType::CenterDrill: case setup::ToolType::SpotDrill: return 2;
    case setup::ToolType::Reamer: return 4;
    default: return 2;
  }
}

}  // namespace

CuttingData cutting_data(const setup::Tool& tool, Cut cut, const Options& options) {
  const MaterialData m = data_of(options.material);
  const double d = std::max(tool.diameter, 0.1);
  const double scale = std::clamp(d / 10.0, 0.3, 2.0);
  double speed = 0, feed_per_rev = 0;
  switch (cut) {
    case Cut::Facing:
    case Cut::Milling: speed = m.milling_speed, feed_per_rev = m.feed_per_tooth * scale * teeth_of(tool); break;
    case Cut::Slotting:
    case Cut::HoleMilling: speed = m.milling_speed, feed_per_rev = 0.7 * m.feed_per_tooth * scale * teeth_of(tool); break;
    case Cut::Drilling: speed = m.drilling_speed, feed_per_rev = m.feed_per_rev * scale; break;
    case Cut::CenterDrilling: speed = 0.7 * m.drilling_speed, feed_per_rev = 0.5 * m.feed_per_rev * scale; break;
    case Cut::Reaming: speed = 0.5 * m.drilling_speed, feed_per_rev = 2 * m.feed_per_rev * scale; break;
  }
  CuttingData c;
  c.rpm = std::min(options.max_spindle_rpm, speed * 1000 / (std::numbers::pi * d));
  c.rpm = std::round(c.rpm);
  c.feed = std::round(feed_per_rev * c.rpm);
  if (tool.spindle_rpm > 0) {
    c.rpm = tool.spindle_rpm;
    c.from_tool_list = true;
  }
  if (tool.feed > 0) {
    c.feed = tool.feed;
    c.from_tool_list = true;
  } else if (tool.spindle_rpm > 0) {
    c.feed = std::round(feed_per_rev * c.rpm);
  }
  const bool axial = cut == Cut::Drilling || cut == Cut::CenterDrilling || cut == Cut::Reaming;
  c.plunge = tool.plunge_feed > 0 ? tool.plunge_feed : axial ? c.feed : std::round(0.3 * c.feed);
  return c;
}

}  // namespace ncbridge::process_planner
