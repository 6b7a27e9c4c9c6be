// G38.2-G38.5 straight probing (LinuxCNC convert_probe) and what the standalone interpreter
// `rs274` then reads back from its simulated machine (set_probe_data): a part program run without
// a machine has no probe input, so the probe is taken to stop at the programmed end point.
#include <cmath>

#include "executor.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

namespace {
// rs274's simulated probe backs off from the trip point towards where the move started, as a
// machine's probing routine does: 0.01 inch, 0.254 mm (saicanon STRAIGHT_PROBE).
constexpr double kBackoffInch = 0.01;
constexpr double kBackoffMm = 0.254;
}  // namespace

void Executor::probe(const BlockCommand& b, int motion) {
  const std::uint32_t col = b.g_column[kGMotion] ? b.g_column[kGMotion] : 1;
  // probe_type: bit 0 = no error without contact (G38.3, G38.5), bit 1 = until contact is lost.
  const auto probe_type = static_cast<std::uint8_t>(motion - 382);
  if (s_.comp_side != Side::Off) fail(col, "Cannot probe with cutter radius comp on");
  if (s_.feed_rate == 0.0) fail(col, "Cannot probe with zero feed rate");
  if (s_.feed_mode == FeedMode::UnitsPerRevolution) fail(col, "Cannot probe with feed per rev mode");
  const Pose end = find_end(b, false);
  if ((probe_type & 1) == 0 && end == s_.position) fail(col, "Start point too close to probe point");
  emit(TurnProbeOn{});
  emit(StraightProbe{end, probe_type});
  emit(TurnProbeOff{});
  s_.motion = motion;

  // What rs274 reads back before the next line: the trip point (#5061-#5066 X Y Z A B C; its
  // simulation has no U V W: #5067-#5069 are 0), #5070 = 0 (its probe input never changes), and
  // the position backed off towards the start. U V W read back as 0 too.
  const double trip[6] = {end.x, end.y, end.z, end.a, end.b, end.c};
  for (int i = 0; i < 6; ++i) params_.set_numbered(5061 + i, trip[i]);
  for (int i = 6; i < 10; ++i) params_.set_numbered(5061 + i, 0.0);
  Pose after = end;
  const double dx = s_.position.x - end.x, dy = s_.position.y - end.y, dz = s_.position.z - end.z;
  const double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (distance != 0) {
    const double backoff = s_.units == Units::Millimeters ? kBackoffMm : kBackoffInch;
    after.x = end.x + backoff * dx / distance;
    after.y = end.y + backoff * dy / distance;
    after.z = end.z + backoff * dz / distance;
  }
  after.u = after.v = after.w = 0;
  s_.position = after;
}

}  // namespace ncbridge::interpreter
