// Coordinate systems and offsets: G54-G59.3, G10 L1/L2/L10/L20, G28/G30 (+.1), G92 family,
// and the parameters that hold them (#5161-#5390).
#include <cmath>
#include <numbers>

#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

namespace {
constexpr double Pose::*kFields[9] = {&Pose::x, &Pose::y, &Pose::z, &Pose::a, &Pose::b,
                                      &Pose::c, &Pose::u, &Pose::v, &Pose::w};
constexpr char kLetters[9] = {'x', 'y', 'z', 'a', 'b', 'c', 'u', 'v', 'w'};
bool is_linear(int axis) { return axis < 3 || axis > 5; }

void rotate(double& x, double& y, double degrees) {
  if (degrees == 0.0) return;
  const double t = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(t), s = std::sin(t);
  const double x1 = x * c - y * s;
  y = x * s + y * c;
  x = x1;
}
}  // namespace

Pose Executor::origin_mm() const {
  Pose o = s_.g5x_mm[static_cast<std::size_t>(s_.coord_system)];
  if (s_.g92_active) {
    for (auto f : kFields) o.*f += s_.g92_mm.*f;
  }
  return o;
}

void Executor::emit_g5x() {
  emit(SetG5xOffset{s_.coord_system, to_units(s_.g5x_mm[static_cast<std::size_t>(s_.coord_system)])});
}

void Executor::emit_g92() {
  emit(SetG92Offset{s_.g92_active ? to_units(s_.g92_mm) : Pose{}});
}

// Parameters mirror the offsets in machine units: inches, as in LinuxCNC's standalone rs274.
void Executor::write_parameters() {
  constexpr double kMachineUnitMm = 25.4;
  for (int axis = 0; axis < 9; ++axis) {
    double k = is_linear(axis) ? kMachineUnitMm : 1.0;
    params_.set_numbered(5161 + axis, s_.g28_mm.*kFields[axis] / k);
    params_.set_numbered(5181 + axis, s_.g30_mm.*kFields[axis] / k);
    params_.set_numbered(5211 + axis, s_.g92_mm.*kFields[axis] / k);
    for (int system = 1; system <= 9; ++system) {
      params_.set_numbered(5201 + 20 * system + axis, s_.g5x_mm[static_cast<std::size_t>(system)].*kFields[axis] / k);
    }
  }
  for (int system = 1; system <= 9; ++system) {
    params_.set_numbered(5210 + 20 * system, s_.rotation_deg[static_cast<std::size_t>(system)]);
  }
  params_.set_numbered(5210, s_.g92_active ? 1.0 : 0.0);
  params_.set_numbered(5220, s_.coord_system);
}

// The program position moves opposite to the origin (LinuxCNC keeps the machine still).
void Executor::apply_origin_change(const Pose& old_total_mm) {
  Pose now = origin_mm();
  for (int axis = 0; axis < 9; ++axis) {
    double k = is_linear(axis) ? s_.mm_per_unit() : 1.0;
    s_.position.*kFields[axis] += (old_total_mm.*kFields[axis] - now.*kFields[axis]) / k;
  }
}

// The current point in the coordinates of `system` (program units): through the active G92
// offset, the active rotation and origin, then back by the other system's origin, rotation and
// the G92 offset (LinuxCNC find_current_in_system).
Pose Executor::current_in_system(int system) const {
  const double k = s_.mm_per_unit();
  Pose p = s_.position;
  const Pose& active = s_.g5x_mm[static_cast<std::size_t>(s_.coord_system)];
  const Pose& other = s_.g5x_mm[static_cast<std::size_t>(system)];
  for (int axis = 0; axis < 9; ++axis) {
    if (s_.g92_active) p.*kFields[axis] += s_.g92_mm.*kFields[axis] / (is_linear(axis) ? k : 1.0);
  }
  rotate(p.x, p.y, s_.rotation());
  for (int axis = 0; axis < 9; ++axis) {
    const double scale = is_linear(axis) ? k : 1.0;
    p.*kFields[axis] += (active.*kFields[axis] - other.*kFields[axis]) / scale;
  }
  rotate(p.x, p.y, -s_.rotation_deg[static_cast<std::size_t>(system)]);
  for (int axis = 0; axis < 9; ++axis) {
    if (s_.g92_active) p.*kFields[axis] -= s_.g92_mm.*kFields[axis] / (is_linear(axis) ? k : 1.0);
  }
  return p;
}

void Executor::do_coordinate_system(int g, std::uint32_t column) {
  int system = g == 540 ? 1 : g == 550 ? 2 : g == 560 ? 3 : g == 570 ? 4 : g == 580 ? 5 : g == 590 ? 6
             : g == 591 ? 7 : g == 592 ? 8 : 9;
  if (s_.comp_side != Side::Off) fail(column, "Cannot change coordinate systems with cutter radius compensation on");
  if (system == s_.coord_system) {
    emit(Comment{"interpreter: continuing to use same coordinate system"});
    return;
  }
  s_.position = current_in_system(system);
  s_.coord_system = system;
  params_.set_numbered(5220, system);
  emit_g5x();
  emit_g92();
  emit(SetXyRotation{s_.rotation()});
}

void Executor::do_g10(const BlockCommand& b) {
  if (!b.has('l')) fail(b.g_column[kGNonModal], "Line with G10 does not have L2, L10, L20 or L1");
  int l = static_cast<int>(std::lround(b.get('l')));
  if (!b.has('p')) fail(b.g_column[kGNonModal], "P word missing with G10");
  double pv = b.get('p');
  int p = static_cast<int>(std::lround(pv));
  double k = s_.mm_per_unit();
  if (l == 2 || l == 20) {
    if (p < 0 || p > 9) fail(b.col('p'), "P value out of range with G10 L" + std::to_string(l));
    int system = p == 0 ? s_.coord_system : p;
    if (system == s_.coord_system && s_.comp_side != Side::Off) {
      fail(b.g_column[kGNonModal], "Cannot change the active coordinate system with cutter radius compensation on");
    }
    Pose& target = s_.g5x_mm[static_cast<std::size_t>(system)];
    const Pose old_g5x = s_.g5x_mm[static_cast<std::size_t>(s_.coord_system)];
    const double old_rotation = s_.rotation();
    if (b.has('r') && l == 20) fail(b.col('r'), "R not allowed in G10 L20");
    double& rotation = s_.rotation_deg[static_cast<std::size_t>(system)];
    if (b.has('r')) rotation = b.get('r');
    if (l == 2) {
      for (int axis = 0; axis < 9; ++axis) {
        if (b.has(kLetters[axis])) target.*kFields[axis] = b.get(kLetters[axis]) * (is_linear(axis) ? k : 1.0);
      }
    } else {
      // L20: the origin that makes the current position read the given values in that system,
      // found as LinuxCNC does: X and Y through the system's rotation
      const Pose here = current_in_system(system);
      double old_x = here.x, old_y = here.y;
      double x = b.has('x') ? b.get('x') : here.x, y = b.has('y') ? b.get('y') : here.y;
      rotate(old_x, old_y, rotation);
      rotate(x, y, rotation);
      if (b.has('x') || b.has('y')) {
        target.x = (old_x - x) * k + target.x;
        target.y = (old_y - y) * k + target.y;
      }
      for (int axis = 2; axis < 9; ++axis) {
        if (!b.has(kLetters[axis])) continue;
        const double scale = is_linear(axis) ? k : 1.0;
        target.*kFields[axis] += (here.*kFields[axis] - b.get(kLetters[axis])) * scale;
      }
    }
    write_parameters();
    if (system != s_.coord_system) emit(Comment{"interpreter: setting coordinate system origin"});
    if (system == s_.coord_system) {
      // the current point, as LinuxCNC moves it: out of the old rotation, by the change of the
      // origin, into the new rotation (the G92 offset takes no part)
      Pose& p = s_.position;
      rotate(p.x, p.y, old_rotation);
      for (int axis = 0; axis < 9; ++axis) {
        const double scale = is_linear(axis) ? k : 1.0;
        p.*kFields[axis] += (old_g5x.*kFields[axis] - target.*kFields[axis]) / scale;
      }
      rotate(p.x, p.y, -rotation);
      emit_g5x();
      emit(SetXyRotation{s_.rotation()});
    }
    return;
  }
  if (l == 1 || l == 10 || l == 11) {
    do_g10_tool(b, l);
    return;
  }
  fail(b.col('l'), "Line with G10 does not have L2, L10, L20 or L1");
}

// G10 L1 (offsets as given), L10 (so that the current position reads the given value in the
// active system), L11 (the same, in G59.3): LinuxCNC convert_setup_tool, on the program's copy
// of the tool table.
void Executor::do_g10_tool(const BlockCommand& b, int l) {
  const int number = nearest_int(b.get('p'));
  ToolEntry* entry = tools_.find(number);
  if (entry == nullptr) {
    if (tool_table_given_ || number <= 0) {
      fail(b.col('p'), "Requested tool " + std::to_string(number) + " not found in the tool table");
    }
    entry = &tools_.find_or_add(number);
  }
  bool any = b.has_axis();
  for (char letter : {'r', 'q', 'i', 'j'}) any = any || b.has(letter);
  if (!any) fail(b.g_column[kGNonModal], "G10 L1 without offsets has no effect");

  const double k = s_.mm_per_unit();
  Pose& offset = entry->offset_mm;
  if (l == 1) {
    for (int axis = 0; axis < 9; ++axis) {
      if (b.has(kLetters[axis])) offset.*kFields[axis] = b.get(kLetters[axis]) * (is_linear(axis) ? k : 1.0);
    }
  } else {
    // The current position in the destination system, without the tool length offset.
    const int system = l == 11 ? 9 : s_.coord_system;
    const double rotation = s_.rotation_deg[static_cast<std::size_t>(system)];
    // (LinuxCNC find_current_in_system_without_tlo; a G10 L11 fixture ignores G92)
    const Pose g5x = to_units(s_.g5x_mm[static_cast<std::size_t>(s_.coord_system)]);
    const Pose destination = to_units(s_.g5x_mm[static_cast<std::size_t>(system)]);
    const Pose g92 = s_.g92_active ? to_units(s_.g92_mm) : Pose{};
    const Pose tool = to_units(s_.tool_offset_mm);
    Pose t = s_.position;
    for (auto f : kFields) t.*f += g92.*f;
    rotate(t.x, t.y, s_.rotation());
    for (auto f : kFields) t.*f += g5x.*f + tool.*f - destination.*f;
    rotate(t.x, t.y, -rotation);
    if (l != 11) {
      for (auto f : kFields) t.*f -= g92.*f;
    }
    if (b.has('x') || b.has('y')) {
      // keep the part of the old offset along the axis not given (in the rotated system)
      double ox = offset.x / k, oy = offset.y / k;
      rotate(ox, oy, -rotation);
      double tx = 0, ty = 0;
      if (b.has('x')) { tx = t.x - b.get('x'); ox = 0; }
      if (b.has('y')) { ty = t.y - b.get('y'); oy = 0; }
      rotate(ox, oy, rotation);
      rotate(tx, ty, rotation);
      offset.x = (tx + ox) * k;
      offset.y = (ty + oy) * k;
    }
    for (int axis = 2; axis < 9; ++axis) {
      if (b.has(kLetters[axis])) {
        offset.*kFields[axis] = (t.*kFields[axis] - b.get(kLetters[axis])) * (is_linear(axis) ? k : 1.0);
      }
    }
  }
  if (b.has('r')) entry->diameter_mm = b.get('r') * k * 2.0;
  if (b.has('i')) entry->frontangle = b.get('i');
  if (b.has('j')) entry->backangle = b.get('j');
  if (b.has('q')) {
    const double q = b.get('q');
    const int orientation = nearest_int(q);
    if (std::fabs(orientation - q) >= 0.0001) fail(b.col('q'), "Q number in G10 is not an integer");
    if (orientation > 9) fail(b.col('q'), "Invalid tool orientation");
    entry->orientation = orientation;
  }
  const int pocket = tools_.pocket_of(number);
  const SetToolTableEntry written{pocket, number, to_units(entry->offset_mm), entry->diameter_mm / k,
                                  entry->frontangle, entry->backangle, entry->orientation};
  emit(written);
  if (pocket == current_pocket_) {
    spindle_tool_ = *entry;
    SetToolTableEntry spindle = written;
    spindle.pocket = 0;
    emit(spindle);
  }
  write_tool_parameters();
}

void Executor::do_home(const BlockCommand& b, int g) {
  if (s_.comp_side != Side::Off) {
    fail(b.g_column[kGNonModal], (g == 281 || g == 301) ? "Cannot set reference point with cutter compensation in effect"
                                                        : "Cannot use g28 or g30 with cutter radius comp");
  }
  double k = s_.mm_per_unit();
  Pose& home = (g == 280 || g == 281) ? s_.g28_mm : s_.g30_mm;
  if (g == 281 || g == 301) {
    Pose origin = origin_mm();
    for (int axis = 0; axis < 9; ++axis) {
      double scale = is_linear(axis) ? k : 1.0;
      home.*kFields[axis] = s_.position.*kFields[axis] * scale + origin.*kFields[axis] +
                            s_.tool_offset_mm.*kFields[axis];
    }
    write_parameters();
    return;
  }
  Pose intermediate = find_end(b, false);
  straight(false, intermediate, nullptr);
  Pose end = s_.position;
  Pose origin = origin_mm();
  bool any = b.has_axis();
  for (int axis = 0; axis < 9; ++axis) {
    if (any && !b.has(kLetters[axis])) continue;
    double scale = is_linear(axis) ? k : 1.0;
    end.*kFields[axis] = (home.*kFields[axis] - origin.*kFields[axis] - s_.tool_offset_mm.*kFields[axis]) / scale;
  }
  straight(false, end, nullptr);
}

void Executor::do_axis_offsets(const BlockCommand& b, int g) {
  double k = s_.mm_per_unit();
  Pose old = origin_mm();
  switch (g) {
    case 920: {
      if (s_.comp_side != Side::Off) fail(b.g_column[kGNonModal], "Cannot change axis offsets with cutter radius comp");
      if (!b.has_axis()) fail(b.g_column[kGNonModal], "All axes missing with G92");
      Pose g5x = s_.g5x_mm[static_cast<std::size_t>(s_.coord_system)];
      for (int axis = 0; axis < 9; ++axis) {
        char letter = kLetters[axis];
        double scale = is_linear(axis) ? k : 1.0;
        double current_g92 = s_.g92_active ? s_.g92_mm.*kFields[axis] : 0.0;
        if (b.has(letter)) {
          // machine position of the tool (program position + origin) must read as `v`
          double machine = s_.position.*kFields[axis] * scale + g5x.*kFields[axis] + current_g92;
          s_.g92_mm.*kFields[axis] = machine - g5x.*kFields[axis] - b.get(letter) * scale;
        } else {
          s_.g92_mm.*kFields[axis] = current_g92;
        }
      }
      s_.g92_active = true;
      break;
    }
    case 520: {
      // G52: a local offset, the G92 offset set to the values given (LinuxCNC: the position
      // moves by the change, unrotated)
      if (s_.comp_side != Side::Off) fail(b.g_column[kGNonModal], "Cannot change axis offsets with cutter radius comp");
      for (int axis = 0; axis < 9; ++axis) {
        const double scale = is_linear(axis) ? k : 1.0;
        const double current_g92 = s_.g92_active ? s_.g92_mm.*kFields[axis] : 0.0;
        s_.g92_mm.*kFields[axis] = b.has(kLetters[axis]) ? b.get(kLetters[axis]) * scale : current_g92;
      }
      s_.g92_active = true;
      break;
    }
    case 921:
      s_.g92_mm = Pose{};
      s_.g92_active = false;
      break;
    case 922:
      s_.g92_active = false;
      break;
    case 923:
      s_.g92_active = true;
      break;
    default:
      break;
  }
  apply_origin_change(old);
  if (g != 922) write_parameters();
  else params_.set_numbered(5210, 0.0);
  emit_g92();
}

}  // namespace ncbridge::interpreter
