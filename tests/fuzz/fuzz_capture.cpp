// libFuzzer target: what a controller or an MTConnect agent sends the capture adapters. An
// MTConnect answer (XML) and the LinuxCNC status reader's lines (JSON) must be refused with an
// InputError or read, never crash; whatever is read drives the run tracker without a crash.
#include <cstdint>
#include <string>
#include <string_view>

#include "ncbridge/capture/linuxcnc_status.hpp"
#include "ncbridge/capture/mtconnect_run.hpp"
#include "ncbridge/capture/mtconnect_streams.hpp"
#include "ncbridge/capture/run_tracker.hpp"
#include "ncbridge/common/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  static const ncbridge::capture::RunProgram program = [] {
    ncbridge::capture::RunProgram p;
    p.text = "G21\nG0 X1\nG1 X2 F100\nM2\n";
    p.order = ncbridge::capture::execution_order("f.ngc", p.text, {});
    return p;
  }();
  ncbridge::capture::RunTracker tracker([](const std::string&) { return program; });
  try {
    const auto streams = ncbridge::capture::parse_mtconnect_streams(input);
    ncbridge::capture::SampleCursor cursor;
    ncbridge::capture::MtconnectDevice device(streams.observations.empty() ? "d" : streams.observations.front().device);
    const auto accepted = cursor.accept(streams);
    for (const auto& s : device.observe(accepted.fresh)) tracker.observe(s);
  } catch (const ncbridge::InputError&) {
  }
  std::size_t start = 0;
  while (start <= input.size()) {
    const std::size_t end = input.find('\n', start);
    const std::string_view line = input.substr(start, end == std::string_view::npos ? input.size() - start : end - start);
    try {
      const auto record = ncbridge::capture::parse_linuxcnc_status_line(line);
      if (record.kind == ncbridge::capture::LinuxcncRecord::Kind::Sample) tracker.observe(record.sample);
    } catch (const ncbridge::InputError&) {
    }
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  tracker.lost("end of input");
  return 0;
}
