#pragma once
// Semantic comparison of two Part 21 files (`ncbridge diff A.stp B.stp`): instances are matched
// by content, not by their #ids. Each instance gets a structural hash of its whole subgraph
// (entity names and attribute values, references replaced by the hash of what they point to,
// reals on the tolerance grid); equal hashes match. What is left is paired within each entity
// type, children before parents, and compared attribute by attribute: the report lists only the
// attributes that differ themselves (a parent that differs only through a child it refers to
// is counted, not listed), grouped by entity type as the tables of Zhang, Nassehi and Newman
// (2015) list the differences between two controllers' STEP-NC files.
#include <cstdint>
#include <string>
#include <vector>

#include "ncbridge/step_writer/express_schema.hpp"
#include "ncbridge/step_writer/part21_graph.hpp"

namespace ncbridge::step_writer {

struct DiffOptions {
  double tolerance = 1e-9;  // absolute, for reals
  // Attributes left out of the comparison: "ENTITY.attribute" with the schema's attribute name
  // (when a schema is given) or its 1-based position; "*" for any entity, e.g. "*.its_id",
  // "CUTTING_TOOL.its_id", "MILLING_TECHNOLOGY.2".
  std::vector<std::string> ignore;
  const express::Schema* schema = nullptr;  // attribute names in the report and in `ignore`
  // Entities left out with everything only they lead to (e.g. TOOLPATH_LIST: compare features,
  // operations and strategies, not the explicit toolpaths); references to them compare equal.
  std::vector<std::string> ignore_entities;
};

struct AttributeDifference {
  std::string entity;
  part21::InstanceId a = 0, b = 0;
  std::string attribute;  // name (with a schema) or "#N" (1-based position)
  std::string value_a, value_b;
};

struct UnpairedInstance {
  std::string entity;
  part21::InstanceId id = 0;
  std::string text;  // ENTITY(attributes), shortened
};

struct DiffResult {
  std::size_t instances_a = 0, instances_b = 0;
  std::size_t matched = 0;               // pairs with the same content
  std::size_t changed_through_parts = 0; // pairs that differ only in instances they refer to
  std::vector<AttributeDifference> differences;
  std::vector<UnpairedInstance> only_a, only_b;
  bool identical() const { return differences.empty() && only_a.empty() && only_b.empty(); }
};

DiffResult semantic_diff(const part21::Graph& a, const part21::Graph& b, const DiffOptions& options);

// The report: a summary, then one table per entity type (entity, attribute, value A, value B),
// then the instances only one file has.
std::string format_diff(const DiffResult& result, const std::string& name_a, const std::string& name_b);

}  // namespace ncbridge::step_writer
