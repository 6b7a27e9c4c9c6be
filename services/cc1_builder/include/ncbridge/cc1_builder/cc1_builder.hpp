#pragma once
// The cc1_builder stage: a canonical call stream -> the CC1 model of ISO 14649 (workingsteps with
// explicit toolpaths, rapid movements, drilling-family operations on round holes).
// The segmentation rules are in docs/cc1.md. The builder is a canonical::Sink: feed it the
// interpreter's stream, then take_project() after end(). Its working state is constant in
// program length; the project it builds holds the toolpaths.
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

class Cc1Builder final : public canonical::Sink {
 public:
  explicit Cc1Builder(Options options);
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
