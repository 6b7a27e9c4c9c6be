#pragma once
// The CC2 features of ISO 14649-10 (PLANAR_FACE, CLOSED_POCKET, OPEN_POCKET, SLOT, STEP,
// GENERAL_OUTSIDE_PROFILE, REGION as REGION_PROJECTION) written into the model writer's stream
// (cc1_writer.cpp writes the project, its CC1 features and every operation). The shared
// geometry (named placements, planes, directions, curves) stays with the model writer.
#include <string_view>
#include <vector>

#include "ncbridge/stepnc/features.hpp"
#include "part21_instance_stream.hpp"

namespace ncbridge::step_writer::cc2 {

class SharedGeometry {
 public:
  virtual ~SharedGeometry() = default;
  virtual part21::InstanceId placement(const stepnc::Axis2Placement3d& a, std::string_view name) = 0;
  virtual part21::InstanceId plane(const stepnc::Plane& p, std::string_view name) = 0;
  virtual part21::InstanceId direction(const stepnc::Direction& d) = 0;
  virtual part21::InstanceId curve(const stepnc::CompositeCurve& c) = 0;
  virtual part21::InstanceId toleranced(const stepnc::TolerancedLengthMeasure& t) = 0;
};

// True for the features write_feature writes (all but TOOLPATH_FEATURE and ROUND_HOLE).
bool is_cc2_feature(const stepnc::Feature& feature);

// Writes what the feature refers to, then the feature; returns the feature's id.
part21::InstanceId write_feature(part21::InstanceStream& s, SharedGeometry& g, const stepnc::Feature& feature,
                                 part21::InstanceId workpiece, const std::vector<part21::InstanceId>& operations);

}  // namespace ncbridge::step_writer::cc2
