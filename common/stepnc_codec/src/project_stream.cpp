#include "ncbridge/stepnc_codec/project_stream.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>

#include "model_fields.hpp"

namespace ncbridge::stepnc_codec {
namespace {

using namespace ncbridge::stepnc;
using detail::Decoder;
using detail::Encoder;
using detail::kVersion;

constexpr std::string_view kShellMagic = "NCBS";
constexpr std::string_view kChunkMagic = "NCBC";

// Everything of the project but its three long sequences.
Project shell_of(const Project& p) {
  Project s;
  s.its_id = p.its_id;
  s.main_workplan.its_id = p.main_workplan.its_id;
  s.workpiece = p.workpiece;
  s.rawpiece = p.rawpiece;
  s.setup = p.setup;
  s.tools = p.tools;
  s.technologies = p.technologies;
  s.machine_functions = p.machine_functions;
  return s;
}

template <class T>
void sequence(Encoder& enc, std::span<const T> items) {
  enc(static_cast<std::uint64_t>(items.size()));
  for (const T& item : items) enc(item);
}

void expect_header(Decoder& dec, std::string_view bytes, std::string_view magic, const char* what) {
  if (dec.take(std::min(bytes.size(), magic.size())) != magic) dec.fail(std::string("not a model ") + what + " (magic)");
  std::uint32_t version = 0;
  dec(version);
  if (version != kVersion)
    dec.fail("model format version " + std::to_string(version) + ", expected " + std::to_string(kVersion));
}

}  // namespace

ProjectParts split_project(const Project& project, std::size_t chunk_bytes) {
  ProjectParts parts;
  parts.shell = std::string(kShellMagic);
  Encoder(parts.shell)(kVersion, shell_of(project));

  const auto& elements = project.main_workplan.its_elements;
  std::size_t features_sent = 0, operations_sent = 0, first = 0;
  std::string body;
  Encoder enc(body);
  const auto flush = [&](std::size_t end, bool last) {
    std::size_t features_end = features_sent, operations_end = operations_sent;
    for (std::size_t i = first; i < end; ++i) {
      if (const auto* ws = std::get_if<MachiningWorkingstep>(&elements[i])) {
        features_end = std::max<std::size_t>(features_end, ws->its_feature.index + std::size_t{1});
        operations_end = std::max<std::size_t>(operations_end, ws->its_operation.index + std::size_t{1});
      }
    }
    if (last) {
      features_end = project.features.size();
      operations_end = project.operations.size();
    }
    features_end = std::min(features_end, project.features.size());
    operations_end = std::min(operations_end, project.operations.size());
    std::string chunk(kChunkMagic);
    Encoder out(chunk);
    out(kVersion, static_cast<std::uint64_t>(end - first));
    chunk += body;
    sequence(out, std::span(project.features).subspan(features_sent, features_end - features_sent));
    sequence(out, std::span(project.operations).subspan(operations_sent, operations_end - operations_sent));
    parts.chunks.push_back(std::move(chunk));
    body.clear();
    first = end;
    features_sent = features_end;
    operations_sent = operations_end;
  };
  for (std::size_t i = 0; i < elements.size(); ++i) {
    enc(elements[i]);
    if (body.size() >= chunk_bytes && i + 1 < elements.size()) flush(i + 1, false);
  }
  flush(elements.size(), true);
  return parts;
}

void ProjectJoiner::shell(std::string_view bytes) {
  Decoder dec(bytes);
  expect_header(dec, bytes, kShellMagic, "shell");
  Project p;
  dec(p);
  dec.expect_end();
  if (!p.main_workplan.its_elements.empty() || !p.features.empty() || !p.operations.empty())
    dec.fail("a model shell with workplan elements, features or operations");
  project_ = std::move(p);
  has_shell_ = true;
}

void ProjectJoiner::chunk(std::string_view bytes) {
  Decoder dec(bytes);
  if (!has_shell_) dec.fail("a model chunk before the model's shell");
  expect_header(dec, bytes, kChunkMagic, "chunk");
  std::vector<Executable> elements;
  std::vector<Feature> features;
  std::vector<Operation> operations;
  dec(elements, features, operations);
  dec.expect_end();
  const std::size_t feature_count = project_.features.size() + features.size();
  const std::size_t operation_count = project_.operations.size() + operations.size();
  for (const Executable& e : elements) {
    const auto* ws = std::get_if<MachiningWorkingstep>(&e);
    if (ws && (ws->its_feature.index >= feature_count || ws->its_operation.index >= operation_count))
      dec.fail("workingstep " + ws->its_id + " names a feature or operation that has not come");
  }
  auto move_into = [](auto& to, auto& from) { to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end())); };
  move_into(project_.main_workplan.its_elements, elements);
  move_into(project_.features, features);
  move_into(project_.operations, operations);
}

Project ProjectJoiner::take() {
  Project out = std::move(project_);
  project_ = Project{};
  has_shell_ = false;
  return out;
}

}  // namespace ncbridge::stepnc_codec

namespace ncbridge::stepnc_codec {
namespace {

constexpr std::string_view kElementsMagic = "NCBE";

template <class T>
std::vector<T> added_since(const std::vector<T>& table, std::size_t& sent) {
  if (table.size() < sent) throw std::logic_error("ElementChunker: a project table shrank");
  std::vector<T> added(table.begin() + static_cast<std::ptrdiff_t>(sent), table.end());
  sent = table.size();
  return added;
}

// A trajectory's own technology and machine functions must have come in this or an earlier chunk.
void check_toolpath_refs(Decoder& dec, const Project& project, const std::string& element_id,
                         const std::optional<ToolpathList>& toolpath) {
  if (!toolpath) return;
  for (const CutterLocationTrajectory& t : toolpath->its_list) {
    const bool known = (!t.its_technology || t.its_technology->index < project.technologies.size()) &&
                       (!t.its_machine_functions || t.its_machine_functions->index < project.machine_functions.size());
    if (!known) dec.fail("streamed element " + element_id + " has a toolpath naming a technology or machine functions that has not come");
  }
}

}  // namespace

void ElementChunker::element(const Project& project, const Executable& element) {
  Encoder enc(body_);
  enc(element);
  if (const auto* ws = std::get_if<MachiningWorkingstep>(&element))
    enc(project.feature(ws->its_feature), project.operation(ws->its_operation));
  ++elements_;
}

std::string ElementChunker::take_chunk(const Project& project) {
  std::string chunk(kElementsMagic);
  Encoder out(chunk);
  out(kVersion, project.workpiece, project.rawpiece, added_since(project.tools, tools_sent_),
      added_since(project.technologies, technologies_sent_), added_since(project.machine_functions, machine_functions_sent_),
      static_cast<std::uint64_t>(elements_));
  chunk += body_;
  body_.clear();
  elements_ = 0;
  return chunk;
}

void ElementUnchunker::chunk(std::string_view bytes, const ElementFn& each) {
  Decoder dec(bytes);
  expect_header(dec, bytes, kElementsMagic, "element chunk");
  std::vector<MillingCuttingTool> tools;
  std::vector<MillingTechnology> technologies;
  std::vector<MillingMachineFunctions> machine_functions;
  std::uint64_t count = 0;
  dec(project_.workpiece, project_.rawpiece, tools, technologies, machine_functions, count);
  auto append = [](auto& to, auto& from) { to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end())); };
  append(project_.tools, tools);
  append(project_.technologies, technologies);
  append(project_.machine_functions, machine_functions);
  for (std::uint64_t i = 0; i < count; ++i) {
    Executable element;
    dec(element);
    project_.features.clear();
    project_.operations.clear();
    if (const auto* ws = std::get_if<MachiningWorkingstep>(&element)) {
      if (ws->its_feature.index != 0 || ws->its_operation.index != 0)
        dec.fail("streamed workingstep " + ws->its_id + " does not name its own feature and operation");
      dec(project_.features.emplace_back(), project_.operations.emplace_back());
      const bool known = std::visit(
          [&](const MachiningOperation& op) {
            return op.its_tool.index < project_.tools.size() && op.its_technology.index < project_.technologies.size() &&
                   op.its_machine_functions.index < project_.machine_functions.size();
          },
          project_.operations.back());
      if (!known) dec.fail("streamed workingstep " + ws->its_id + " names a tool, technology or machine functions that has not come");
      std::visit([&](const MachiningOperation& op) { check_toolpath_refs(dec, project_, ws->its_id, op.its_toolpath); },
                 project_.operations.back());
    } else if (const auto* rapid = std::get_if<RapidMovement>(&element)) {
      check_toolpath_refs(dec, project_, rapid->its_id, rapid->its_toolpath);
    }
    each(project_, element);
    ++elements_;
  }
  dec.expect_end();
}

}  // namespace ncbridge::stepnc_codec
