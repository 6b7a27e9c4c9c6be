#pragma once
// The AP224 feature kinds, one reader each (ap224_holes.cpp, ap224_pockets.cpp,
// ap224_slots_steps.cpp, ap224_faces_profiles.cpp, ap224_listed.cpp, ap224_stock.cpp).
// Everything is read in the part frame; ap224_reader.cpp turns it into the setup frame.
#include <optional>
#include <string>
#include <vector>

#include "ap224_graph.hpp"
#include "ncbridge/part_reader/part.hpp"

namespace ncbridge::part_reader::ap224 {

// What a feature reader gives back: the feature, or why it is only listed.
struct ReadFeature {
  std::optional<Feature> feature;
  std::optional<ListedFeature> listed;
  std::vector<Warning> warnings;
};

ReadFeature read_round_hole(const Graph& g, InstanceId id);
ReadFeature read_pocket(const Graph& g, InstanceId id);
ReadFeature read_slot(const Graph& g, InstanceId id);
ReadFeature read_step(const Graph& g, InstanceId id, const std::optional<PartStock>& stock);
ReadFeature read_flat_face(const Graph& g, InstanceId id, const std::optional<PartStock>& stock);
ReadFeature read_outside_profile(const Graph& g, InstanceId id);
ListedFeature list_feature(const Graph& g, InstanceId id, const std::string& entity, const std::string& reason);
// The holes of a composite hole, outermost (largest) first; `holes` maps ROUND_HOLE ids to their
// index in the part's features.
std::optional<Compound> read_composite_hole(const Graph& g, InstanceId id, const std::vector<std::pair<InstanceId, std::size_t>>& holes,
                                            const std::vector<Feature>& features, std::vector<Warning>& warnings);
std::optional<PartStock> read_stock(const Graph& g, std::vector<Warning>& warnings);

// Shared helpers.
// A length the component must give, else InputError at the feature; a length that may be absent (0).
double required_length(const Graph& g, InstanceId feature, InstanceId component, const Parameters& p, const char* name);
double optional_length(const Parameters& p, const char* name);
std::string where(InstanceId id);  // "#12"
const Component* find_component(const Graph& g, const std::vector<Component>& components,
                                std::initializer_list<const char*> entities, const char* aspect = nullptr);
stepnc::Direction negate(const stepnc::Direction& d);
stepnc::Direction cross(const stepnc::Direction& a, const stepnc::Direction& b);
double dot(const stepnc::Direction& a, const stepnc::Direction& b);
// `ref` made normal to `axis` (or any normal when parallel).
stepnc::Direction normal_part(const stepnc::Direction& ref, const stepnc::Direction& axis);
stepnc::CartesianPoint moved(const stepnc::CartesianPoint& p, const stepnc::Direction& d, double distance);
// The first placement of a parameter set: 'orientation', else any.
std::optional<stepnc::Axis2Placement3d> orientation(const Parameters& p);
std::optional<stepnc::Direction> any_direction(const Parameters& p);
// Corners (with "the edge to the next corner is open") in a placement's xy plane, counter-clockwise.
std::vector<OutlineVertex> local_outline(const std::vector<std::pair<stepnc::CartesianPoint, bool>>& corners,
                                         const stepnc::Axis2Placement3d& placement);

}  // namespace ncbridge::part_reader::ap224
