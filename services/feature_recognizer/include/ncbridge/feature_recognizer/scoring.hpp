#pragma once
// Scoring recognised features against ground truth (the corpus truth.json files).
// A recognised feature matches a true one when: same type; centre within 1 mm for closed
// features (holes, closed pockets, closed slots) or 5 mm for open ones (faces, steps, open
// pockets, through slots, outside profiles); top_z and bottom_z within 0.2 mm; hole diameter
// within 0.05 mm. Each feature matches at most once (closest first).
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/feature_recognizer/feature.hpp"

namespace ncbridge::feature_recognizer {

struct TruthFeature {
  std::string id;
  FeatureType type = FeatureType::Region;
  double x = 0, y = 0, top_z = 0, bottom_z = 0;
  std::optional<double> diameter;  // round holes
  bool closed = false;
};

// Reads the features of a truth file: a cam part's truth.json ("features": [...]) or, with
// `program` set, the entry of that program in the paper's truth.json. Throws InputError.
std::vector<TruthFeature> read_truth(const std::filesystem::path& file, const std::string& program = "");

struct TypeScore {
  int truth = 0, recognized = 0, matched = 0;
  double precision() const;
  double recall() const;
  double f1() const;
};

struct ScoreMatch {
  std::size_t truth_index, recognized_index;
  double position_error;
};

struct Score {
  std::map<FeatureType, TypeScore> per_type;
  TypeScore overall;
  std::vector<ScoreMatch> matches;
  double mean_position_error() const;  // over matches, 0 when none
};

Score score(const std::vector<RecognizedFeature>& recognized, const std::vector<TruthFeature>& truth);

}  // namespace ncbridge::feature_recognizer
