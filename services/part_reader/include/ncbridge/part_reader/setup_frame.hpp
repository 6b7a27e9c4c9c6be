#pragma once
// The setup frame: the part frame turned so that the side facing the spindle (ReadOptions::up)
// is +Z, then moved by ReadOptions::offset. Readers map what they read through it, so features,
// stock and bounds come out in the frame the planner and the program use.
#include <array>
#include <optional>
#include <string>

#include "ncbridge/part_reader/part.hpp"
#include "ncbridge/stepnc/geometry.hpp"

namespace ncbridge::part_reader {

class SetupFrame {
 public:
  explicit SetupFrame(const ReadOptions& options = {});

  stepnc::CartesianPoint point(const stepnc::CartesianPoint& p) const;
  stepnc::Direction direction(const stepnc::Direction& d) const;
  stepnc::Axis2Placement3d placement(const stepnc::Axis2Placement3d& p) const;
  stepnc::Direction to_part(const stepnc::Direction& d) const;  // the inverse turn
  // Row-major 3x3 rotation and the offset (for readers that transform geometry themselves).
  const std::array<double, 9>& rotation() const { return r_; }
  const std::array<double, 3>& offset() const { return t_; }
  SetupUp up() const { return up_; }

 private:
  SetupUp up_;
  std::array<double, 9> r_;
  std::array<double, 3> t_;
};

// Moves everything of a part read in the setup frame (features, stock, bounds) by `offset`.
void move_part(Part& part, const std::array<double, 3>& offset);

// The setup that brings a part-frame direction to +Z when it is one of the six axis
// directions (within 1e-6), else nothing.
std::optional<SetupUp> setup_facing(const stepnc::Direction& part_direction);

// "(0, 1, 0)", rounded to 1e-6.
std::string direction_text(const stepnc::Direction& d);

// Why a feature whose z is not the setup's +Z is not planned: its axis in the part frame and the
// setup it needs ("axis (0, -1, 0) in the part frame: needs a setup with -y up (--setup -y)").
std::string needed_setup_text(const stepnc::Direction& part_axis);

}  // namespace ncbridge::part_reader
