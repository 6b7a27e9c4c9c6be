// The setup frame: each side brought to +Z by a proper rotation, then moved.
#include <gtest/gtest.h>

#include <cmath>

#include "ncbridge/part_reader/setup_frame.hpp"

namespace pr = ncbridge::part_reader;
using ncbridge::stepnc::CartesianPoint;
using ncbridge::stepnc::Direction;

namespace {

Direction side_of(pr::SetupUp up) {
  switch (up) {
    case pr::SetupUp::PlusZ: return {0, 0, 1};
    case pr::SetupUp::MinusZ: return {0, 0, -1};
    case pr::SetupUp::PlusX: return {1, 0, 0};
    case pr::SetupUp::MinusX: return {-1, 0, 0};
    case pr::SetupUp::PlusY: return {0, 1, 0};
    case pr::SetupUp::MinusY: return {0, -1, 0};
  }
  return {};
}

}  // namespace

TEST(SetupFrame, EverySideComesUpAndTheTurnIsARotation) {
  for (pr::SetupUp up : {pr::SetupUp::PlusZ, pr::SetupUp::MinusZ, pr::SetupUp::PlusX, pr::SetupUp::MinusX, pr::SetupUp::PlusY,
                         pr::SetupUp::MinusY}) {
    const pr::SetupFrame frame(pr::ReadOptions{up, {0, 0, 0}});
    const Direction z = frame.direction(side_of(up));
    EXPECT_NEAR(z.z, 1, 1e-12) << to_string(up);
    const auto& r = frame.rotation();
    const double det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) + r[2] * (r[3] * r[7] - r[4] * r[6]);
    EXPECT_NEAR(det, 1, 1e-12) << to_string(up);
    EXPECT_EQ(pr::setup_facing(side_of(up)), up);
    const Direction back = frame.to_part(z);
    EXPECT_NEAR(back.x, side_of(up).x, 1e-12);
    EXPECT_NEAR(back.y, side_of(up).y, 1e-12);
    EXPECT_NEAR(back.z, side_of(up).z, 1e-12);
  }
}

TEST(SetupFrame, OffsetMovesPointsNotDirections) {
  const pr::SetupFrame frame(pr::ReadOptions{pr::SetupUp::MinusZ, {10, 20, 30}});
  const CartesianPoint p = frame.point({1, 2, 3});
  EXPECT_DOUBLE_EQ(p.x, 11);
  EXPECT_DOUBLE_EQ(p.y, 18);
  EXPECT_DOUBLE_EQ(p.z, 27);
  const Direction d = frame.direction({0, 1, 0});
  EXPECT_DOUBLE_EQ(d.y, -1);
}

TEST(SetupFrame, NeededSetupIsSaid) {
  EXPECT_EQ(pr::needed_setup_text({0, -1, 0}), "axis (0, -1, 0) in the part frame: needs a setup with -y up (--setup -y)");
  EXPECT_EQ(pr::needed_setup_text({0.5, 0, std::sqrt(0.75)}),
            "axis (0.5, 0, 0.866025) in the part frame: needs a tilted setup (5-axis or a fixture at an angle)");
  EXPECT_EQ(pr::setup_up_from_string("-x"), pr::SetupUp::MinusX);
  EXPECT_EQ(pr::setup_up_from_string("z"), pr::SetupUp::PlusZ);
  EXPECT_FALSE(pr::setup_up_from_string("up").has_value());
}
