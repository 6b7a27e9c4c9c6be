#pragma once
// Navigation of an AP224 (ISO 10303-224, feature_based_process_planning) instance graph: who
// refers to whom, the parameters a feature or feature component carries (its
// shape_representation_with_parameters items: placements, measures in mm or degrees, texts,
// directions), the components hung on its shape aspects, and units. Every malformed piece is an
// InputError at the instance's line.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/part21_graph.hpp"
#include "ncbridge/stepnc/geometry.hpp"

namespace ncbridge::part_reader::ap224 {

namespace p21 = step_writer::part21;
using p21::InstanceId;

// The items of a feature's (or component's) parameter representations, by item name.
struct Parameters {
  std::map<std::string, stepnc::Axis2Placement3d> placements;  // mm, unit directions
  std::map<std::string, double> lengths;                        // mm
  std::map<std::string, double> angles;                         // degrees
  std::map<std::string, double> counts;                         // unitless measures
  std::map<std::string, std::string> texts;                     // descriptive items
  std::map<std::string, std::pair<double, double>> tolerances;  // a measure's upper and lower deviation (mm / degrees)
  std::map<std::string, stepnc::Direction> directions;          // direction_shape_representation, by its name ('' if none)
  std::vector<std::pair<std::string, std::string>> listing;     // every item as "name" = "value unit", in file order
};

// A component reached from a feature: through a shape aspect of the feature's shape (the
// aspect's description, e.g. 'diameter occurrence') and a shape_aspect_relationship (its name
// and description, e.g. 'diameter' / 'profile usage'), or related to the feature directly.
struct Component {
  std::string aspect;        // the shape aspect's description ('' when related directly)
  std::string relation_name;
  std::string relation_description;
  InstanceId id = 0;         // the component (or, related directly, the other feature)
};

class Graph {
 public:
  Graph(const p21::Graph& graph, std::string file);

  const p21::Instance& at(InstanceId id) const;  // InputError when absent
  SourceLocation where(InstanceId id) const;
  const std::string& file() const { return file_; }
  const p21::Graph& graph() const { return graph_; }

  // Instances whose attributes refer to `id` (anywhere, also inside lists), in file order.
  const std::vector<InstanceId>& users(InstanceId id) const;

  // The entity names of an instance (one for a simple instance).
  static bool is(const p21::Instance& instance, std::string_view entity);
  // The shape_aspect attributes (name, description, of_shape, product_definitional) of a
  // shape_aspect subtype, simple or complex: the last four attributes of the record holding them.
  std::optional<std::pair<std::string, std::string>> aspect_text(const p21::Instance& instance) const;
  std::optional<InstanceId> aspect_of_shape(const p21::Instance& instance) const;
  // name / description of a characterized_object (features) or a shape aspect.
  std::string description_of(const p21::Instance& instance) const;

  Parameters parameters(InstanceId id) const;  // merged over all its property definitions
  Parameters representation(InstanceId rep) const;  // the items of one representation
  std::vector<Component> components(InstanceId feature) const;

  double length_unit_mm(InstanceId unit) const;     // mm per unit
  double angle_unit_degrees(InstanceId unit) const; // degrees per unit
  double context_length_mm(InstanceId context) const;
  std::string context_length_name(InstanceId context) const;  // "inch", "mm", "m", ...

  // Safe accessors: InputError at the instance when the attribute is missing or of another kind.
  const p21::Value& attribute(const p21::Instance& instance, const p21::Record& record, std::size_t index) const;
  std::string text(const p21::Instance& instance, const p21::Record& record, std::size_t index) const;
  double number(const p21::Instance& instance, const p21::Value& value) const;
  InstanceId reference(const p21::Instance& instance, const p21::Value& value) const;
  const std::vector<p21::Value>& list(const p21::Instance& instance, const p21::Value& value) const;
  [[noreturn]] void fail(InstanceId id, const std::string& message) const;

  stepnc::Axis2Placement3d placement(InstanceId id, double scale) const;
  stepnc::Direction direction(InstanceId id) const;
  stepnc::CartesianPoint point(InstanceId id, double scale) const;

 private:
  void read_item(InstanceId item, double length_scale, Parameters& out) const;
  void read_representation(InstanceId rep, Parameters& out) const;
  double unit_scale(InstanceId unit, bool angle, int depth) const;

  const p21::Graph& graph_;
  std::string file_;
  std::unordered_map<InstanceId, std::vector<InstanceId>> users_;
  std::vector<InstanceId> none_;
};

}  // namespace ncbridge::part_reader::ap224
