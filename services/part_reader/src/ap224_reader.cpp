#include "ncbridge/part_reader/ap224_reader.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "ap224_features.hpp"
#include "ncbridge/part_reader/setup_frame.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"

namespace ncbridge::part_reader {

namespace {

using namespace ap224;

constexpr std::string_view kTurning[] = {"OUTER_ROUND", "REVOLVED_PROFILE", "THREAD", "TURNED_KNURL", "GEAR"};
constexpr std::string_view kTransition[] = {"CHAMFER", "EDGE_ROUND", "FILLET"};
constexpr std::string_view kUnmapped[] = {"BOSS", "MARKING", "SPHERICAL_CAP", "ROUNDED_END", "RIB_TOP", "PROTRUSION",
                                          "REMOVAL_VOLUME", "CIRCULAR_PATTERN", "RECTANGULAR_PATTERN", "FEATURE_PATTERN",
                                          "REPLICATE_FEATURE", "EXTERNALLY_DEFINED_FEATURE_DEFINITION"};

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// A TAPER that is a component of another feature (an outer round's, a hole's) is listed with it.
bool is_component(const Graph& g, InstanceId id) {
  for (InstanceId u : g.users(id)) {
    const auto& ui = g.at(u);
    for (const char* rel : {"FEATURE_COMPONENT_RELATIONSHIP", "SHAPE_DEFINING_RELATIONSHIP"}) {
      const auto* r = ui.record(rel);
      if (r && r->attributes.size() >= 4 && r->attributes[2].reference_if() && r->attributes[2].reference_if()->id == id) return true;
    }
  }
  return false;
}

void take(const Graph& g, ReadFeature&& read, Part& part, std::vector<std::pair<InstanceId, std::size_t>>* holes, InstanceId id) {
  for (auto& w : read.warnings) part.warnings.push_back(std::move(w));
  if (read.feature) {
    read.feature->line = g.where(id).line;
    if (holes) holes->emplace_back(id, part.features.size());
    part.features.push_back(std::move(*read.feature));
  }
  if (read.listed) part.listed.push_back(std::move(*read.listed));
}

}  // namespace

bool is_ap224(const step_writer::part21::Header& header) {
  for (const auto& name : header.schema) {
    if (upper(name).find("FEATURE_BASED_PROCESS_PLANNING") != std::string::npos) return true;
  }
  return false;
}

Part read_ap224(const step_writer::part21::Graph& graph, const std::string& file_name, const ReadOptions& options) {
  Graph g(graph, file_name);
  Part part;
  part.file = file_name;
  part.format = "AP224";
  part.file_units = "mm";
  for (const auto& instance : graph.instances()) {
    if (const auto* p = instance.record("PRODUCT"); p && !p->attributes.empty() && p->attributes[0].is_string()) {
      part.name = p->attributes[0].as_string();
      break;
    }
  }
  for (const auto& instance : graph.instances()) {
    if (Graph::is(instance, "GLOBAL_UNIT_ASSIGNED_CONTEXT")) {
      part.file_units = g.context_length_name(instance.id);
      break;
    }
  }
  part.stock = read_stock(g, part.warnings);

  std::vector<std::pair<InstanceId, std::size_t>> holes;
  std::vector<InstanceId> composites;
  for (const auto& instance : graph.instances()) {
    const InstanceId id = instance.id;
    if (Graph::is(instance, "ROUND_HOLE")) {
      take(g, read_round_hole(g, id), part, &holes, id);
    } else if (Graph::is(instance, "COMPOSITE_HOLE")) {
      composites.push_back(id);
    } else if (Graph::is(instance, "POCKET")) {
      take(g, read_pocket(g, id), part, nullptr, id);
    } else if (Graph::is(instance, "SLOT")) {
      take(g, read_slot(g, id), part, nullptr, id);
    } else if (Graph::is(instance, "STEP")) {
      take(g, read_step(g, id, part.stock), part, nullptr, id);
    } else if (Graph::is(instance, "FLAT_FACE")) {
      take(g, read_flat_face(g, id, part.stock), part, nullptr, id);
    } else if (Graph::is(instance, "OUTSIDE_PROFILE")) {
      take(g, read_outside_profile(g, id), part, nullptr, id);
    } else {
      for (auto e : kTurning) {
        if (Graph::is(instance, e)) part.listed.push_back(list_feature(g, id, std::string(e), "turning feature: not planned for milling"));
      }
      for (auto e : kTransition) {
        if (Graph::is(instance, e)) part.listed.push_back(list_feature(g, id, std::string(e), "transition feature: not planned"));
      }
      if (Graph::is(instance, "TAPER") && !is_component(g, id)) {
        part.listed.push_back(list_feature(g, id, "TAPER", "turning feature: not planned for milling"));
      }
      for (auto e : kUnmapped) {
        if (Graph::is(instance, e)) part.listed.push_back(list_feature(g, id, std::string(e), "this kind of feature is not planned"));
      }
    }
  }
  for (InstanceId id : composites) {
    if (auto c = read_composite_hole(g, id, holes, part.features, part.warnings)) {
      for (std::size_t e : c->elements) part.features[e].compound = static_cast<int>(part.compounds.size());
      part.compounds.push_back(std::move(*c));
    }
  }
  for (const auto& l : part.listed) {
    part.warnings.push_back({l.source, l.entity + (l.name.empty() ? "" : " '" + l.name + "'") + ": " + l.reason});
  }

  // Into the setup frame: features not facing the spindle are kept, marked and said.
  const SetupFrame frame(options);
  for (auto& f : part.features) {
    const stepnc::Direction part_axis = f.placement.axis;
    f.placement = frame.placement(f.placement);
    f.accessible = std::abs(f.placement.axis.z - 1) < 1e-6;
    if (!f.accessible) {
      part.warnings.push_back({f.source, upper(to_string(f.kind)) + ": " + needed_setup_text(part_axis) + "; not planned"});
    }
  }
  if (part.stock) part.stock->placement = frame.placement(part.stock->placement);
  if (part.features.empty()) part.warnings.push_back({"", "the file has no machining feature this reader plans"});
  return part;
}

Part read_ap224_file(const std::filesystem::path& path, const ReadOptions& options) {
  const auto read = step_writer::part21::read_part21_file(path);
  return read_ap224(read.graph, path.string(), options);
}

}  // namespace ncbridge::part_reader
