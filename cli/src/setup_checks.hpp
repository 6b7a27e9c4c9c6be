#pragma once
// Checks that catch a wrong setup, which would otherwise give a wrong result without an error
// (rules and thresholds: docs/cli.md#warnings):
//   feed           a feed implausible for its tool (a program posted in mm/s read as mm/min)
//   outside_stock  cutting moves outside the stock
//   security_plane a security plane inside or below the stock
//   units          program and stock in different length units
//   tool_type      a tool the program uses has no type in the tool list
// They read the CC1 model element by element (so streamed CC1 is checked too), plus what only
// the canonical stream tells (ProgramFacts: file names, the units the program cuts in).
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/stepnc/project.hpp"
#include "warning.hpp"

namespace ncbridge::cli {

// What the canonical call stream says that the CC1 model does not keep.
class ProgramFacts {
 public:
  void source_file(std::uint32_t index, std::string_view path);
  void call(const canonical::Call& c);
  // The file and first line of a workingstep's source lines.
  SourceLocation where(const stepnc::SourceLines& lines) const;
  // The length units in effect at the first cutting move, and where they were set.
  const std::optional<canonical::Units>& cutting_units() const { return cutting_units_; }
  const SourceLocation& units_set_at() const { return units_set_at_; }

 private:
  std::vector<std::string> files_;
  canonical::Units units_ = canonical::Units::Millimeters;
  SourceLocation units_where_;
  std::optional<canonical::Units> cutting_units_;
  SourceLocation units_set_at_;
};

struct SetupCheckInputs {
  std::string program;                   // as messages name it
  std::optional<setup::Stock> stock;     // --stock (else the CC1 file's rawpiece is used)
  std::string stock_file;
  const setup::ToolList* tools = nullptr;  // --tools
  std::string tools_file;
  std::optional<double> security_plane;  // --security-plane, when given
  bool heidenhain_per_minute = false;    // Heidenhain F words read as mm/min (the hint)
};

class SetupChecks {
 public:
  SetupChecks(SetupCheckInputs inputs, const ProgramFacts* facts);

  // Each workplan element, in order (`project` as cc1_builder::WorkplanSink describes it).
  void element(const stepnc::Project& project, const stepnc::Executable& element);
  // Once, with the finished project (its setup holds the security plane).
  void finish(const stepnc::Project& project);
  const std::vector<Warning>& warnings() const { return warnings_; }

 private:
  void check_feed(const stepnc::Project& project, const stepnc::MachiningWorkingstep& ws);
  void check_inside_stock(const stepnc::Project& project, const stepnc::MachiningWorkingstep& ws);
  SourceLocation where(const stepnc::SourceLines& lines) const;
  // Adds a warning; past the tenth of a kind, only counts it (finish() says how many more).
  void report(const std::string& kind, SourceLocation where, std::string message);
  const setup::Stock* stock() const { return stock_ ? &*stock_ : nullptr; }

  SetupCheckInputs inputs_;
  const ProgramFacts* facts_;
  std::optional<setup::Stock> stock_;
  std::set<std::pair<std::uint32_t, std::uint32_t>> feeds_checked_;  // (tool, technology)
  std::map<std::string, std::pair<std::size_t, std::size_t>> per_kind_;  // reported, not reported
  std::vector<Warning> warnings_;
};

}  // namespace ncbridge::cli
