// Tools and spindle: T (SELECT_TOOL), M6, M61, G43/G43.1/G49, M3/M4/M5, G96/G97.
#include <cmath>

#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

void Executor::do_tool_select(const BlockCommand& b) {
  double t = b.get('t');
  int tool = static_cast<int>(std::lround(t));
  if (tool < 0) fail(b.col('t'), "Negative tool id used");
  if (tool != 0 && tool_table_given_ && tools_.find(tool) == nullptr) {
    fail(b.col('t'), "Requested tool " + std::to_string(tool) + " not found in the tool table");
  }
  s_.selected_tool = tool;
  emit(SelectTool{tool});
}

void Executor::do_tool_change(const BlockCommand& b) {
  int m = b.m[kMToolChange];
  if (m == 61) {
    if (!b.has('q')) fail(b.m_column[kMToolChange], "Q word missing with M61");
    int tool = static_cast<int>(std::lround(b.get('q')));
    if (tool < 0) fail(b.col('q'), "Need non-negative Q-word to specify tool number with M61");
    s_.tool_in_spindle = tool;
    s_.selected_tool = tool;
    current_pocket_ = tools_.pocket_of(tool);
    emit(ChangeToolNumber{tool, current_pocket_});
    write_tool_parameters();
    return;
  }
  if (s_.comp_side != Side::Off) fail(b.m_column[kMToolChange], "Cannot change tools with cutter radius compensation on");
  int tool = s_.selected_tool < 0 ? s_.tool_in_spindle : s_.selected_tool;
  emit(StartChange{});
  emit(StopSpindleTurning{0});
  s_.spindle = Direction::Stopped;
  // LinuxCNC passes the tool's pocket (its index in the tool table), not its number.
  current_pocket_ = tools_.pocket_of(tool);
  emit(ChangeTool{current_pocket_});
  s_.tool_in_spindle = tool;
  const ToolEntry* entry = tool_entry(tool);
  spindle_tool_ = entry != nullptr ? *entry : ToolEntry{};
  write_tool_parameters();
}

// #5400-#5413: the tool in the spindle: number, offsets, diameter, angles, orientation. Lengths
// in machine units (inches), as in LinuxCNC's standalone rs274.
void Executor::write_tool_parameters() {
  constexpr double kMachineUnitMm = 25.4;
  const ToolEntry* t = &spindle_tool_;
  const Pose& o = t->offset_mm;
  const double values[14] = {static_cast<double>(s_.tool_in_spindle > 0 ? s_.tool_in_spindle : 0),
                             o.x / kMachineUnitMm, o.y / kMachineUnitMm, o.z / kMachineUnitMm, o.a, o.b, o.c,
                             o.u / kMachineUnitMm, o.v / kMachineUnitMm, o.w / kMachineUnitMm,
                             t->diameter_mm / kMachineUnitMm, t->frontangle, t->backangle,
                             static_cast<double>(t->orientation)};
  for (int i = 0; i < 14; ++i) params_.set_numbered(5400 + i, values[i]);
}

void Executor::do_spindle(const BlockCommand& b) {
  switch (b.m[kMSpindle]) {
    case 3:
      emit(StartSpindleClockwise{0});
      s_.spindle = Direction::Clockwise;
      break;
    case 4:
      emit(StartSpindleCounterclockwise{0});
      s_.spindle = Direction::Counterclockwise;
      break;
    case 5:
      emit(StopSpindleTurning{0});
      s_.spindle = Direction::Stopped;
      break;
    case 70: case 71: case 72: case 73:
      do_modal_context(b, b.m[kMSpindle]);
      break;
    default: {
      // M19: orient when R or P is given, wait when Q is (LinuxCNC convert_m).
      if (b.has('r') && (b.get('r') < 0.0 || b.get('r') > 360.0)) {
        fail(b.col('r'), "R value must be within 0..360 with M19");
      }
      int mode = 0;
      if (b.has('p')) {
        const double p = b.get('p');
        mode = static_cast<int>(std::lround(p));
        if (p != mode || mode < 0 || mode > 2) fail(b.col('p'), "P value must be 0,1,or 2 with M19");
      }
      if (b.has('q') && b.get('q') <= 0.0) fail(b.col('q'), "Q word with M19 requires a value > 0");
      if (b.has('r') || b.has('p')) emit(OrientSpindle{0, b.has('r') ? b.get('r') : 0.0, mode});
      if (b.has('q')) emit(WaitSpindleOrientComplete{0, b.get('q')});
      s_.spindle = Direction::Stopped;
      break;
    }
  }
}

void Executor::do_spindle_mode(const BlockCommand& b, int g) {
  if (g == 960) {
    double max = b.has('d') ? std::fabs(b.get('d')) : 1e30;  // LinuxCNC: no D, no limit
    emit(SetSpindleMode{0, max});
    s_.css = true;
  } else {
    emit(SetSpindleMode{0, 0.0});
    s_.css = false;
  }
}

void Executor::do_tool_length_offset(const BlockCommand& b, int g) {
  if (s_.comp_side != Side::Off) {
    fail(b.g_column[kGToolLength], "Cannot change tool offset with cutter radius compensation on");
  }
  double k = s_.mm_per_unit();
  Pose offset_mm{};
  if (g == 490) {
    // all zero
  } else if (g == 430) {
    if (b.has('h')) {
      const int tool = static_cast<int>(std::lround(b.get('h')));
      if (tool < 0) fail(b.col('h'), "Negative H word tool length offset index used");
      if (tool != 0) {
        const ToolEntry* t = tools_.find(tool);
        if (t == nullptr && tool_table_given_) {
          fail(b.col('h'), "Tool " + std::to_string(tool) + " has no tool length offset (not in the tool table)");
        }
        if (t != nullptr) {
          offset_mm = t->offset_mm;
        } else if (!warned_no_tool_length_) {
          // the tool-tip path does not depend on the length: without a tool list it is 0
          warned_no_tool_length_ = true;
          warn(b.col('h'), "G43 H" + std::to_string(tool) +
                               ": no tool list, so no tool lengths: length 0 used (the tool-tip path is the same); "
                               "give --tools for the real lengths");
        }
      }
    } else if (const ToolEntry* t = tool_entry(s_.tool_in_spindle)) {
      // LinuxCNC reads the loaded tool's pocket (also after M61, where rs274's simulated
      // machine forgets the M61 from the next block on)
      offset_mm = t->offset_mm;
    }
  } else if (g == 432) {
    // G43.2: add another tool's offset to the one in effect
    offset_mm = s_.tool_offset_mm;
    if (!b.has('h')) fail(b.g_column[kGToolLength], "G43.2 needs an H word");
    int tool = static_cast<int>(std::lround(b.get('h')));
    if (tool != 0) {
      const ToolEntry* t = tools_.find(tool);
      if (t == nullptr) fail(b.col('h'), "Tool " + std::to_string(tool) + " has no tool length offset (not in the tool table)");
      for (auto f : {&Pose::x, &Pose::y, &Pose::z, &Pose::a, &Pose::b, &Pose::c, &Pose::u, &Pose::v, &Pose::w}) {
        offset_mm.*f += t->offset_mm.*f;
      }
    }
  } else if (g == 431) {
    for (char letter : {'x', 'y', 'z', 'u', 'v', 'w'}) {
      if (!b.has(letter)) continue;
      double v = b.get(letter) * k;
      switch (letter) {
        case 'x': offset_mm.x = v; break;
        case 'y': offset_mm.y = v; break;
        case 'z': offset_mm.z = v; break;
        case 'u': offset_mm.u = v; break;
        case 'v': offset_mm.v = v; break;
        default: offset_mm.w = v; break;
      }
    }
    for (char letter : {'a', 'b', 'c'}) {
      if (!b.has(letter)) continue;
      double v = b.get(letter);
      if (letter == 'a') offset_mm.a = v; else if (letter == 'b') offset_mm.b = v; else offset_mm.c = v;
    }
  }
  Pose old = s_.tool_offset_mm;
  s_.tool_offset_mm = offset_mm;
  Pose& p = s_.position;
  p.x += (old.x - offset_mm.x) / k;
  p.y += (old.y - offset_mm.y) / k;
  p.z += (old.z - offset_mm.z) / k;
  p.a += old.a - offset_mm.a;
  p.b += old.b - offset_mm.b;
  p.c += old.c - offset_mm.c;
  p.u += (old.u - offset_mm.u) / k;
  p.v += (old.v - offset_mm.v) / k;
  p.w += (old.w - offset_mm.w) / k;
  emit(UseToolLengthOffset{to_units(offset_mm)});
}

}  // namespace ncbridge::interpreter
