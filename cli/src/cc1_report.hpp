#pragma once
// The --report JSON of a CC1 conversion (docs/formats/report.md), written while the workplan is
// built: each workplan element's entry goes out as the element is finished, so the report of a
// program of any length costs a few MB. It goes to an OutputFile of the run's OutputSet, which
// makes it appear with the Part 21 file or not at all.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "output_files.hpp"
#include "warning.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::cli {

class Cc1Report {
 public:
  struct Head {
    std::string program, output, level;
  };
  struct Tail {
    std::uint64_t canonical_calls = 0;
    std::uint64_t output_bytes = 0;
    std::vector<Warning> warnings;
    std::vector<std::pair<std::string, double>> timings_ms;
  };

  Cc1Report(OutputFile& out, const Head& head);
  ~Cc1Report();
  Cc1Report(const Cc1Report&) = delete;
  Cc1Report& operator=(const Cc1Report&) = delete;

  // One finished workplan element (see cc1_builder::WorkplanSink for what `project` holds).
  void element(const stepnc::Project& project, const stepnc::Executable& element);
  // The rest of the report (tools from the finished project).
  void finish(const stepnc::Project& project, const Tail& tail);

 private:
  void flush_text();
  void flush_features();

  OutputFile& file_;
  std::FILE* features_;  // the "features" entries, copied in after the workplan's
  std::string text_, feature_text_;
  bool first_element_ = true, first_feature_ = true;
};

}  // namespace ncbridge::cli
