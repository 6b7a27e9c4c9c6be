// Recognises every program of the recognition corpus and prints, per part, the recognised
// features and the per-type precision / recall / F1 against truth, and how many of the truth's
// operations of the matched features agree (type, tool, strategy); then the totals.
//   usage: feature_recognition_score [--verbose] [--reports DIR] [source_dir shared_dir]
// With --reports, the features are not recognised here but read from DIR/<case>.json, the
// reports of `ncbridge convert --level cc2` (end to end through our interpreter;
// score_end_to_end.sh makes them from the comment-stripped programs).
#include <cstdio>
#include <cstring>
#include <array>
#include <map>
#include <string>

#include "ncbridge/common/error.hpp"
#include "recognition_corpus.hpp"

namespace fr = ncbridge::feature_recognizer;

namespace {

// A report's features (docs/formats/report.md) as recogniser output, for the scorer.
std::vector<fr::RecognizedFeature> report_features(const std::string& file) {
  std::vector<fr::RecognizedFeature> out;
  for (const auto& t : fr::read_truth(file)) {
    fr::RecognizedFeature f;
    f.type = t.type;
    f.x = t.x, f.y = t.y, f.top_z = t.top_z, f.bottom_z = t.bottom_z;
    f.diameter = t.diameter.value_or(0);
    if (t.type == fr::FeatureType::Slot) {
      f.slot_ends = t.closed ? std::array{fr::SlotEnd::Radiused, fr::SlotEnd::Radiused} : std::array{fr::SlotEnd::Open, fr::SlotEnd::Open};
    }
    out.push_back(f);
  }
  return out;
}

void print_row(const char* name, const fr::TypeScore& s) {
  std::printf("  %-24s truth %3d  found %3d  matched %3d  P %.3f  R %.3f  F1 %.3f\n", name, s.truth, s.recognized,
              s.matched, s.precision(), s.recall(), s.f1());
}

}  // namespace

int main(int argc, char** argv) {
  bool verbose = false;
  std::string source = NCBRIDGE_SOURCE_DIR, shared = NCBRIDGE_SHARED_DIR, reports;
  int positional = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--verbose") == 0) verbose = true;
    else if (std::strcmp(argv[i], "--reports") == 0 && i + 1 < argc) reports = argv[++i];
    else if (positional++ == 0) source = argv[i];
    else shared = argv[i];
  }
  std::map<fr::FeatureType, fr::TypeScore> totals;
  double error_sum = 0;
  int matches = 0;
  fr::TypeScore operations;
  try {
    for (const auto& c : ncbridge::test_support::recognition_corpus(source, shared)) {
      const auto features = reports.empty() ? ncbridge::test_support::recognize_case(c)
                                            : report_features(reports + "/" + c.name + ".json");
      const auto truth = fr::read_truth(c.truth, c.truth_program);
      const auto s = fr::score(features, truth);
      std::printf("%s: F1 %.3f (%d truth, %d found, %d matched), mean position error %.3f mm\n", c.name.c_str(),
                  s.overall.f1(), s.overall.truth, s.overall.recognized, s.overall.matched, s.mean_position_error());
      if (reports.empty()) {
        const auto ops = fr::score_operations(features, truth, s);
        std::printf("  operations of the matched features: %d of %d agree with truth (type, tool, strategy)\n", ops.matched,
                    ops.truth);
        operations.truth += ops.truth, operations.matched += ops.matched;
      }
      if (verbose) {
        for (std::size_t i = 0; i < features.size(); ++i) {
          const auto& f = features[i];
          std::printf("    found %-24s at (%8.3f, %8.3f) z %7.3f..%7.3f d %6.3f", std::string(fr::to_string(f.type)).c_str(),
                      f.x, f.y, f.top_z, f.bottom_z, f.diameter);
          if (f.profile.shape != fr::ProfileShape::None) {
            std::printf("  profile L %.4f W %.4f R %.4f C %.4f angle %.2f D %.4f", f.profile.length, f.profile.width,
                        f.profile.corner_radius, f.profile.corner_chamfer, f.profile.angle_deg, f.profile.diameter);
          }
          for (const auto& op : f.operations) {
            std::printf("  [%s T%d %s]", std::string(fr::to_string(op.type)).c_str(), op.tool_number,
                        std::string(fr::to_string(op.strategy)).c_str());
          }
          std::printf("\n");
        }
        for (const auto& t : truth) {
          std::printf("    truth %-4s %-24s at (%8.3f, %8.3f) z %7.3f..%7.3f\n", t.id.c_str(),
                      std::string(fr::to_string(t.type)).c_str(), t.x, t.y, t.top_z, t.bottom_z);
        }
      }
      for (const auto& [type, ts] : s.per_type) {
        print_row(std::string(fr::to_string(type)).c_str(), ts);
        auto& tot = totals[type];
        tot.truth += ts.truth, tot.recognized += ts.recognized, tot.matched += ts.matched;
      }
      error_sum += s.mean_position_error() * static_cast<double>(s.matches.size());
      matches += static_cast<int>(s.matches.size());
    }
  } catch (const ncbridge::InputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", e.where().to_string().c_str(), e.message().c_str());
    return 1;
  }
  std::printf("all parts:\n");
  fr::TypeScore all;
  for (const auto& [type, ts] : totals) {
    print_row(std::string(fr::to_string(type)).c_str(), ts);
    all.truth += ts.truth, all.recognized += ts.recognized, all.matched += ts.matched;
  }
  print_row("overall", all);
  std::printf("  mean position error %.3f mm over %d matches\n", matches ? error_sum / matches : 0.0, matches);
  if (reports.empty()) std::printf("  operations: %d of %d agree with truth\n", operations.matched, operations.truth);
  return 0;
}
