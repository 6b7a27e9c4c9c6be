#include "ncbridge/capture/linuxcnc_status.hpp"

#include <nlohmann/json.hpp>

#include "ncbridge/common/error.hpp"

namespace ncbridge::capture {
namespace {

[[noreturn]] void bad(const std::string& message) { throw InputError({"<linuxcnc status>", 0, 0}, message); }

}  // namespace

LinuxcncRecord parse_linuxcnc_status_line(std::string_view line) {
  const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object()) bad("not a JSON object: " + std::string(line.substr(0, 120)));
  LinuxcncRecord r;
  try {
    const std::string kind = j.at("kind").get<std::string>();
    if (kind == "sample") {
      r.kind = LinuxcncRecord::Kind::Sample;
      const std::string mode = j.at("mode").get<std::string>();
      r.sample.mode = mode == "auto" ? ControllerSample::Mode::Auto
                      : mode == "mdi" ? ControllerSample::Mode::Mdi
                                      : ControllerSample::Mode::Manual;
      const std::string interp = j.at("interp").get<std::string>();
      r.sample.interp = interp == "idle"     ? ControllerSample::Interp::Idle
                        : interp == "paused" ? ControllerSample::Interp::Paused
                                             : ControllerSample::Interp::Running;
      r.sample.program = j.at("program").get<std::string>();
      const auto line_number = j.at("line").get<long long>();
      r.sample.line = line_number > 0 ? static_cast<std::uint32_t>(line_number) : 0;
      r.sample.fault_reason = j.at("fault").get<std::string>();
      r.sample.fault = !r.sample.fault_reason.empty();
    } else if (kind == "tools") {
      r.kind = LinuxcncRecord::Kind::Tools;
      r.tool_table = j.at("table").get<std::string>();
      r.inch = j.at("inch").get<bool>();
    } else if (kind == "lost" || kind == "fatal") {
      r.kind = kind == "lost" ? LinuxcncRecord::Kind::Lost : LinuxcncRecord::Kind::Fatal;
      r.reason = j.at("reason").get<std::string>();
    } else {
      bad("unknown record kind \"" + kind + "\"");
    }
  } catch (const nlohmann::json::exception& e) {
    bad(std::string("malformed record: ") + e.what());
  }
  return r;
}

}  // namespace ncbridge::capture
