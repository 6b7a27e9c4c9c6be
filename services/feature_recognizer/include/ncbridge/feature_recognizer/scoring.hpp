#pragma once
// Scoring recognised features against ground truth (the corpus truth.json files).
// A recognised feature matches a true one when: same type; centre within 1 mm for closed
// features (holes, closed pockets, closed slots) or 5 mm for open ones (faces, steps, open
// pockets, through slots, outside profiles); top_z and bottom_z within 0.2 mm; hole diameter
// within 0.05 mm. Each feature matches at most once (closest first).
// Operations are scored on the matched features only: an operation matches when type, tool and
// strategy agree. A truth feature lists them either as "operations": [{type, tool_number,
// strategy}] in ISO 14649 terms (a strategy is read as the longest strategy name the truth's
// text starts with, "contour parallel, 5 layers" = contour_parallel; text naming none is not
// compared), or as FreeCAD's "machined_by": [{op_type, tool_number, strategy}], mapped to ISO
// 14649 by the table of docs/recognition.md ("Operations").
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/feature_recognizer/feature.hpp"

namespace ncbridge::feature_recognizer {

struct TruthOperation {
  OperationType type = OperationType::Drilling;
  int tool_number = 0;
  // Any of these is right (FreeCAD's ZigZagOffset is either order of zigzag and contour); empty
  // when the truth describes the strategy in words that name none.
  std::vector<Strategy> strategies;
  std::string source;  // what the truth said, for messages
};

// The ISO 14649 operations of a feature of `type` that FreeCAD's operations made (the truth's
// "machined_by" entries, in order). Throws InputError for an operation it has no mapping for.
std::vector<TruthOperation> freecad_operations(const std::vector<std::pair<std::string, std::string>>& op_type_and_strategy,
                                               const std::vector<int>& tool_numbers, FeatureType type,
                                               const std::string& file, const std::string& id);

struct TruthFeature {
  std::string id;
  FeatureType type = FeatureType::Region;
  double x = 0, y = 0, top_z = 0, bottom_z = 0;
  std::optional<double> diameter;  // round holes
  // A closed pocket's or an outside profile's outline as the truth states it (its
  // "dimensions"): a rectangle's length, width and corner radius or 45° corner chamfer, or a
  // circle's diameter.
  std::optional<double> length, width, corner_radius, corner_chamfer, profile_diameter;
  bool closed = false;
  std::vector<TruthOperation> operations;  // empty when the truth does not list them
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

// The operations of the matched features whose truth lists operations: `truth` counts the true
// operations, `recognized` the recognised ones of those features, `matched` the pairs that agree
// (each used once, in machining order).
TypeScore score_operations(const std::vector<RecognizedFeature>& recognized, const std::vector<TruthFeature>& truth,
                           const Score& features);

}  // namespace ncbridge::feature_recognizer
