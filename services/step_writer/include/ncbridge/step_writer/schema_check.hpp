#pragma once
// Checks every instance of a Part 21 graph against an EXPRESS schema: known, instantiable entity;
// attribute count; `$` only for OPTIONAL attributes; references to instances of an allowed type
// (through SELECTs and defined types); enumeration values; basic types; aggregate bounds.
// Errors versus warnings are decided in docs/formats/part21.md ("Schema check rules").
#include <string>
#include <vector>

#include "ncbridge/step_writer/diagnostic.hpp"
#include "ncbridge/step_writer/express_schema.hpp"
#include "ncbridge/step_writer/part21_graph.hpp"

namespace ncbridge::step_writer {

struct CheckOptions {
  std::string file_name;  // put into each diagnostic's location
  // Accept entity names of other ISO 14649 editions / STEP parts that real files use (draft
  // versus published names, Part 42 curves outside the schema's subset) with a warning.
  bool known_variants_are_warnings = true;
};

std::vector<Diagnostic> check_instances(const part21::Graph& graph, const express::Schema& schema,
                                        const CheckOptions& options = {});

}  // namespace ncbridge::step_writer

