// CPU time of recognition alone, on one thread: reads a CC1 file (ncbridge convert --level cc1)
// and times the recogniser's three steps with the thread's CPU clock, so the figure holds on a
// shared, loaded machine where wall time does not.
//   usage: recognition_cpu_time PART_CC1.stp
#include <time.h>

#include <cstdio>
#include <exception>

#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/to_stepnc.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace {

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  namespace fr = ncbridge::feature_recognizer;
  if (argc != 2) {
    std::fprintf(stderr, "usage: recognition_cpu_time PART_CC1.stp\n");
    return 2;
  }
  try {
    const auto cc1 = ncbridge::step_writer::read_stepnc_file(argv[1]).project;
    const auto stock = fr::stock_from_cc1(cc1);
    if (!stock) {
      std::fprintf(stderr, "%s: no rawpiece\n", argv[1]);
      return 1;
    }
    const double t0 = thread_cpu_seconds();
    const auto workingsteps = fr::workingsteps_from_cc1(cc1);
    const double t1 = thread_cpu_seconds();
    const auto features = fr::recognize(workingsteps, *stock);
    const double t2 = thread_cpu_seconds();
    const auto cc2 = fr::cc2_from_cc1(cc1, features);
    const double t3 = thread_cpu_seconds();
    std::printf("workingsteps %.3f recognize %.3f cc2_model %.3f total %.3f features %zu\n", t1 - t0, t2 - t1, t3 - t2,
                t3 - t0, features.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
