#pragma once
// What a CC2 manufacturing feature removes, in the program frame: the XY region (closed
// outlines of lines and arcs), the height it starts at and its floor. The material check
// builds the designed part from these; the toolpath generator clears them. The rules per
// feature (docs/toolpaths.md, "Feature geometry"):
//   ROUND_HOLE      a circle of the diameter; floor at the depth (the drill point's tip for a
//                   CONICAL_HOLE_BOTTOM); THROUGH holes reach the part's bottom there.
//   PLANAR_FACE     the face_boundary, else the removal_boundary (local x, profile_length)
//                   swept along the course_of_travel (its direction and distance).
//   CLOSED_POCKET   its feature_boundary: RECTANGULAR (length along local x, width, the
//                   orthogonal_radius at the corners), CIRCULAR, GENERAL (the closed curve).
//   OPEN_POCKET     open_boundary and wall_boundary joined into one outline; without a
//                   wall_boundary, the open_boundary closed by a straight open side.
//   SLOT            its course (LINEAR_PATH) swept by its width (the swept_shape's
//                   profile_length): radiused ends are half circles about the course's ends,
//                   open ends run out of the part, flat ends are square.
//   STEP            from its wall (the open_boundary LINEAR_PATH along local x) towards local
//                   +y, to the stock's edge.
//   GENERAL_OUTSIDE_PROFILE  everything of the stock outside its closed feature_boundary.
//   REGION          the projected outline, to its depth (a planar region).
// Bad geometry (no depth, a non-positive size, a profile that does not close, a placement not
// along +Z) throws InputError naming the feature.
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/material_check/planar_curve.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/features.hpp"

namespace ncbridge::material_check {

// A feature's local frame in XY: origin, the direction of local x, and the origin's height.
struct PlanarFrame {
  Point2 origin;
  double angle = 0;  // of local x from +X, radians
  double z = 0;

  Point2 to_program(double u, double v) const;
  Point2 to_program(Point2 local) const { return to_program(local.x, local.y); }
  Point2 to_local(Point2 p) const;
};

struct FeatureRegion {
  std::string id;
  std::size_t feature_index = 0;  // in the project's features
  PlanarFrame frame;
  // Closed outlines, even-odd: outer boundaries counter-clockwise, holes clockwise.
  std::vector<PlanarCurve> outline;
  // Stretches of the outline the tool must run out over (open sides the feature itself
  // declares: a slot's open ends, an open pocket's missing side, a step's and a face's sides).
  std::vector<PlanarCurve> open_edges;
  double top_z = 0;
  double floor_z = 0;   // top - depth (a through feature's depth reaches the part's bottom)
  double depth = 0;     // as the feature states it (top to its depth plane)
  bool through = false;
  // ROUND_HOLE with a conical bottom: the floor rises from floor_z at the axis with the point.
  std::optional<double> cone_tip_angle;
  std::optional<double> hole_radius;  // ROUND_HOLE: its radius (the outline is this circle)
};

// The region of project.features[index]. `stock` bounds steps and outside profiles and tells
// what is through. Throws InputError (file = `source_name`) for a feature without usable geometry.
FeatureRegion feature_region(const stepnc::Feature& feature, std::size_t index, const setup::Stock& stock,
                             const std::string& source_name = "");

// The frame of a feature's placement (throws InputError when its axis is not +Z).
PlanarFrame frame_of(const stepnc::Axis2Placement3d& placement, const std::string& feature_id,
                     const std::string& source_name = "");

// A CompositeCurve (POLYLINEs and TRIMMED_CURVEs on circles about the local z axis) given in
// `frame`'s coordinates, as a planar curve in the program frame.
PlanarCurve planar_curve_of(const stepnc::CompositeCurve& curve, const PlanarFrame& frame);

}  // namespace ncbridge::material_check
