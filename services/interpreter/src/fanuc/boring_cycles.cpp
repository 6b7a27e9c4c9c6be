#include "fanuc/boring_cycles.hpp"

#include <cmath>
#include <initializer_list>

namespace ncbridge::interpreter::fanuc {

using lowering::DialectMachine;
using lowering::NeutralBlock;
using lowering::NeutralWord;

namespace {

class Spelling {
 public:
  Spelling(DialectMachine& m, std::uint32_t column) : m_(m), column_(column) {}

  void rapid(double x, double y, double z) { move(0, x, y, z); }
  void feed(double x, double y, double z) { move(1, x, y, z); }
  void dwell(double seconds) {
    if (seconds > 0) run({{'g', 4, column_}, {'p', seconds, column_}});
  }
  // Fanuc's oriented spindle stop (OSS): the spindle stops at its orientation angle.
  void oriented_stop() {
    run({{'m', 5, column_}});
    run({{'m', 19, column_}, {'r', 0, column_}, {'p', 0, column_}});
  }
  void spindle_on(canonical::Direction direction) {
    run({{'m', direction == canonical::Direction::Counterclockwise ? 4.0 : 3.0, column_}});
  }

 private:
  void move(int g, double x, double y, double z) {
    run({{'g', static_cast<double>(g), column_}, {'x', x, column_}, {'y', y, column_}, {'z', z, column_}});
  }
  void run(std::initializer_list<NeutralWord> words) {
    NeutralBlock nb;
    nb.words.assign(words);
    m_.execute(nb);
  }
  DialectMachine& m_;
  std::uint32_t column_;
};

canonical::CycleTag tag_of(const DialectMachine& m, const BoringHole& h, std::uint16_t g_code_x10, double clearance) {
  canonical::CycleTag tag;
  tag.g_code_x10 = g_code_x10;
  tag.retract_to_r = m.state().retract == RetractMode::RPlane && g_code_x10 != 870;
  tag.plane = 0;
  tag.x = h.x;
  tag.y = h.y;
  tag.clearance = clearance;
  tag.r = h.r;
  tag.z = h.z;
  tag.q = h.q;
  tag.p = h.dwell;
  tag.repeat = static_cast<std::uint32_t>(h.repeat);
  return tag;
}

canonical::Direction turning_spindle(const DialectMachine& m, const char* cycle, std::uint32_t column) {
  const canonical::Direction d = m.state().spindle;
  if (d == canonical::Direction::Stopped) m.fail(column, std::string("Spindle not turning in ") + cycle);
  return d;
}

}  // namespace

void fine_boring(DialectMachine& m, const BoringHole& h, std::uint32_t column) {
  if (h.r < h.z) m.fail(column, "G76: the R point is below the hole bottom Z");
  const canonical::Direction spindle = turning_spindle(m, "G76", column);
  const bool to_r = m.state().retract == RetractMode::RPlane;
  const double clear = to_r ? h.r : std::max(h.initial, h.r);
  Spelling s(m, column);
  m.begin_spelled_hole(tag_of(m, h, 860, clear));
  // positioning at the current level (the tool is at R or above it, or is brought up to R first)
  const canonical::Pose& at = m.state().position;
  if (at.z < h.r) s.rapid(at.x, at.y, h.r);
  const double level = std::max(at.z, h.r);
  s.rapid(h.x, h.y, level);
  if (level > h.r) s.rapid(h.x, h.y, h.r);
  s.feed(h.x, h.y, h.z);
  s.dwell(h.dwell);
  s.oriented_stop();
  s.rapid(h.x + h.shift_x, h.y + h.shift_y, h.z);
  s.rapid(h.x + h.shift_x, h.y + h.shift_y, clear);
  s.rapid(h.x, h.y, clear);
  s.spindle_on(spindle);
  m.end_spelled_hole();
}

void back_boring(DialectMachine& m, const BoringHole& h, std::uint32_t column) {
  if (h.r > h.z) m.fail(column, "G87: the R point (where back boring starts) is above Z (where it ends)");
  if (h.initial < h.z) m.fail(column, "G87: the initial level is below Z");
  const canonical::Direction spindle = turning_spindle(m, "G87", column);
  Spelling s(m, column);
  m.begin_spelled_hole(tag_of(m, h, 870, h.initial));
  const double level = m.state().position.z;  // positioning at the current level
  if (level < h.z) m.fail(column, "G87: the tool is below Z when the cycle starts");
  s.rapid(h.x, h.y, level);
  s.oriented_stop();
  s.rapid(h.x + h.shift_x, h.y + h.shift_y, level);
  s.rapid(h.x + h.shift_x, h.y + h.shift_y, h.r);
  s.rapid(h.x, h.y, h.r);
  s.spindle_on(spindle);
  s.feed(h.x, h.y, h.z);
  s.dwell(h.dwell);
  s.oriented_stop();
  s.rapid(h.x + h.shift_x, h.y + h.shift_y, h.z);
  s.rapid(h.x + h.shift_x, h.y + h.shift_y, h.initial);
  s.rapid(h.x, h.y, h.initial);
  s.spindle_on(spindle);
  m.end_spelled_hole();
}

}  // namespace ncbridge::interpreter::fanuc
