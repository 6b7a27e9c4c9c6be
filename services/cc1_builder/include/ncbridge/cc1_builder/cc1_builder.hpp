#pragma once
// The cc1_builder stage: a canonical call stream -> the CC1 model of ISO 14649 (workingsteps with
// explicit toolpaths, rapid movements, drilling-family operations on round holes).
// The segmentation rules are in docs/cc1.md. The builder is a canonical::Sink: feed it the
// interpreter's stream, then take_project() after end(). Its working state is constant in
// program length; the project it builds holds the toolpaths, unless a WorkplanSink takes each
// workplan element as soon as it is finished (streamed CC1: then memory stays flat).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::cc1_builder {

struct Options {
  setup::ToolList tools;                 // mm
  std::optional<setup::Stock> stock;     // program frame, mm
  std::optional<double> security_plane_z;  // mm; default: the highest rapid (else motion) Z
  double helix_chord_tolerance = 0.001;  // mm: helical arcs become polylines within this
  double hole_diameter_tolerance = 0.1;  // mm: the +/- of ROUND_HOLE diameters (G-code has none)
  std::string project_id = "NCBRIDGE CC1";
};

// Something the builder could not represent exactly; the conversion still succeeds.
struct Warning {
  SourceLocation where;
  std::string message;
};

// Receives the workplan element by element, in order, as each is finished.
class WorkplanSink {
 public:
  virtual ~WorkplanSink() = default;
  // `project` holds the tools, technologies and machine functions made so far, the workpiece and
  // rawpiece, and for a machining workingstep its own feature and operation at the indices it
  // names; both are valid during the call only. The element's its_secplane is not set: the
  // security plane is the setup's, known after end().
  virtual void element(const stepnc::Project& project, const stepnc::Executable& element) = 0;
};

class Cc1Builder final : public canonical::Sink {
 public:
  // With `elements`, finished elements go there and the project keeps none (no workplan
  // elements, features or operations): take_project() gives the resources, workpiece and setup.
  explicit Cc1Builder(Options options, WorkplanSink* elements = nullptr);
  ~Cc1Builder() override;
  Cc1Builder(const Cc1Builder&) = delete;
  Cc1Builder& operator=(const Cc1Builder&) = delete;

  void source_file(std::uint32_t index, std::string_view path) override;
  // Throws InputError (with the call's source) for input it cannot convert, e.g. cutting with a
  // tool that is not in the tool list.
  void call(const canonical::Call& call) override;
  void end() override;

  // The finished project; call once, after end().
  stepnc::Project take_project();
  const std::vector<Warning>& warnings() const;
  std::uint64_t calls_seen() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Convenience: runs a whole recorded stream through a builder.
stepnc::Project build_cc1(const std::vector<canonical::Call>& calls, Options options,
                          std::vector<Warning>* warnings = nullptr);

}  // namespace ncbridge::cc1_builder
