#pragma once
// CNC programs through the optimizer: the interpreter's canonical calls as an element stream
// (CanonicalFrontEnd), and an element stream back as canonical calls (to_canonical) for the
// gcode_writer or anything else that takes calls.
//
// STRAIGHT_TRAVERSE, STRAIGHT_FEED and ARC_FEED become motions in program coordinates; every
// other call rides along in place as a canonical call. Motions that must stay as they came are
// kept (Motion::keep): those a canned cycle made (so the writer can write the cycle back), those in
// inverse-time or per-revolution feed mode, the input's arcs; the first motion, and the first
// after an XY rotation, a probe or a rigid tap, start from a position not known (where the
// machine starts from is not in the stream).
#include <cstdint>
#include <string_view>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

class CanonicalFrontEnd final : public canonical::Sink {
 public:
  explicit CanonicalFrontEnd(ElementSink& out) : out_(out) {}
  void source_file(std::uint32_t index, std::string_view path) override;
  void call(const canonical::Call& call) override;
  void end() override { out_.end(); }

  std::uint64_t calls() const { return calls_; }
  std::uint64_t motions() const { return motions_; }
  std::uint64_t arcs() const { return arcs_; }

 private:
  void motion(const canonical::Call& c, MotionKind kind, const canonical::Pose& end);
  void offset_changed(const canonical::Pose& total);

  ElementSink& out_;
  Vec3 position_{};
  std::array<double, 6> rotary_{};
  bool known_ = false;
  double feed_ = 0;
  int feed_mode_ = 0;
  canonical::Units units_ = canonical::Units::Millimeters;
  canonical::Plane plane_ = canonical::Plane::XY;
  canonical::Pose g5x_{}, g92_{}, tool_{};
  std::uint64_t calls_ = 0, motions_ = 0, arcs_ = 0;
};

// The calls of one element (a loop's body is not its business: see gcode output), appended to
// `sink`: motions as STRAIGHT_TRAVERSE / STRAIGHT_FEED / ARC_FEED, calls as they are. Text lines
// (printer files) are not calls: they are written as COMMENTs.
void to_canonical(const Element& element, canonical::Sink& sink);

}  // namespace ncbridge::toolpath_optimizer
