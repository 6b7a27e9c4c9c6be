// plan_timing PART.stp TOOLS.json: reads a B-rep part as `ncbridge plan` does (its bounding box
// as the stock) and prints where the time goes: Open CASCADE's read, the plain face model,
// recognition, planning, the CC2 text; features, workingsteps; the process's peak RSS.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>

#include "ncbridge/common/error.hpp"
#include "ncbridge/part_reader/brep_reader.hpp"
#include "ncbridge/process_planner/planner.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  if (argc != 3) {
    std::fprintf(stderr, "usage: plan_timing PART.stp TOOLS.json\n");
    return 2;
  }
  try {
    ncbridge::part_reader::BrepTimings t;
    const auto t0 = Clock::now();
    ncbridge::part_reader::Part part = ncbridge::part_reader::read_brep_file(argv[1], {}, &t);
    const ncbridge::setup::Stock stock{part.bounds->min, part.bounds->max};
    ncbridge::part_reader::add_stock_features(part, *part.bounds);
    const auto tools = ncbridge::setup::read_tool_list(argv[2]);
    const auto t1 = Clock::now();
    const auto plan = ncbridge::process_planner::plan(part, stock, tools);
    const auto t2 = Clock::now();
    ncbridge::step_writer::StepncWriteOptions options;
    options.unix_time = 0;
    const std::string text = ncbridge::step_writer::write_stepnc(plan.project, options);
    const auto t3 = Clock::now();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
    std::printf("occt_read_ms %.1f model_ms %.1f recognition_ms %.1f plan_ms %.2f cc2_ms %.2f total_ms %.1f features %zu "
                "workingsteps %zu cc2_bytes %zu peak_rss_kb %ld\n",
                t.occt_ms, t.model_ms, t.recognition_ms, ms(t2 - t1), ms(t3 - t2), ms(t3 - t0), part.features.size(),
                plan.project.main_workplan.its_elements.size(), text.size(), usage.ru_maxrss);
  } catch (const ncbridge::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
