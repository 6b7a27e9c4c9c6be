#include "ncbridge/feature_recognizer/scoring.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "ncbridge/common/error.hpp"

namespace ncbridge::feature_recognizer {
namespace {

std::optional<FeatureType> feature_type_from(const std::string& name) {
  static const std::pair<const char*, FeatureType> kNames[] = {
      {"planar_face", FeatureType::PlanarFace}, {"round_hole", FeatureType::RoundHole},
      {"closed_pocket", FeatureType::ClosedPocket}, {"open_pocket", FeatureType::OpenPocket},
      {"slot", FeatureType::Slot}, {"step", FeatureType::Step},
      {"general_outside_profile", FeatureType::GeneralOutsideProfile}, {"region", FeatureType::Region}};
  for (const auto& [n, t] : kNames) {
    if (name == n) return t;
  }
  return std::nullopt;
}

template <typename Enum>
std::optional<Enum> enum_from(const std::string& name, int count) {
  for (int i = 0; i < count; ++i) {
    if (to_string(static_cast<Enum>(i)) == name) return static_cast<Enum>(i);
  }
  return std::nullopt;
}

TruthOperation read_operation(const nlohmann::json& j, const std::string& file, const std::string& id) {
  TruthOperation op;
  const std::string type = j.value("type", std::string{}), strategy = j.value("strategy", std::string{"none"});
  const auto t = enum_from<OperationType>(type, static_cast<int>(OperationType::FreeformOperation) + 1);
  if (!t) throw InputError({file, 0, 0}, "feature '" + id + "' has an operation of unknown type '" + type + "'");
  op.type = *t;
  std::string words;
  for (char c : strategy) words += c == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::size_t longest = 0;
  std::optional<Strategy> named;
  for (int i = 0; i <= static_cast<int>(kLastStrategy); ++i) {
    const auto name = to_string(static_cast<Strategy>(i));
    if (words.rfind(name, 0) == 0 && name.size() > longest) longest = name.size(), named = static_cast<Strategy>(i);
  }
  if (named) op.strategies = {*named};
  op.tool_number = j.value("tool_number", 0);
  op.source = type + " " + strategy;
  return op;
}

bool starts_with(const std::string& text, std::string_view prefix) { return text.rfind(prefix, 0) == 0; }

OperationType milling_type(FeatureType feature, bool finishing) {
  switch (feature) {
    case FeatureType::PlanarFace: return finishing ? OperationType::PlaneFinishMilling : OperationType::PlaneRoughMilling;
    case FeatureType::GeneralOutsideProfile:
      return finishing ? OperationType::SideFinishMilling : OperationType::SideRoughMilling;
    case FeatureType::Region: return OperationType::FreeformOperation;
    default: return finishing ? OperationType::BottomAndSideFinishMilling : OperationType::BottomAndSideRoughMilling;
  }
}

double number(const nlohmann::json& j, const char* key, const std::string& file, const std::string& id) {
  if (!j.contains(key) || !j[key].is_number()) {
    throw InputError({file, 0, 0}, "feature '" + id + "' has no number '" + key + "'");
  }
  return j[key].get<double>();
}

TruthFeature read_feature(const nlohmann::json& j, const std::string& file) {
  TruthFeature t;
  t.id = j.value("id", std::string{});
  const std::string type = j.value("type", std::string{});
  const auto ft = feature_type_from(type);
  if (!ft) throw InputError({file, 0, 0}, "feature '" + t.id + "' has unknown type '" + type + "'");
  t.type = *ft;
  const auto& xy = j.contains("center_xy") ? j["center_xy"] : j.value("position", nlohmann::json{});
  if (!xy.is_array() || xy.size() < 2) throw InputError({file, 0, 0}, "feature '" + t.id + "' has no position");
  t.x = xy[0].get<double>();
  t.y = xy[1].get<double>();
  t.top_z = number(j, "top_z", file, t.id);
  t.bottom_z = number(j, "bottom_z", file, t.id);
  if (j.contains("dimensions") && j["dimensions"].contains("diameter") && t.type == FeatureType::RoundHole) {
    t.diameter = j["dimensions"]["diameter"].get<double>();
  }
  if (j.contains("dimensions") && j["dimensions"].is_object() &&
      (t.type == FeatureType::ClosedPocket || t.type == FeatureType::GeneralOutsideProfile)) {
    const auto& d = j["dimensions"];
    auto read = [&](const char* key, std::optional<double>& into) {
      if (d.contains(key) && d[key].is_number()) into = d[key].get<double>();
    };
    read("length", t.length);
    read("width", t.width);
    read("corner_radius", t.corner_radius);
    read("corner_chamfer", t.corner_chamfer);
    // The CAM parts state an outside profile's sides along x and y.
    std::optional<double> along_x, along_y;
    read("length_x", along_x);
    read("width_y", along_y);
    if (along_x && along_y) t.length = std::max(*along_x, *along_y), t.width = std::min(*along_x, *along_y);
    if (t.corner_chamfer && *t.corner_chamfer <= 0) t.corner_chamfer.reset();  // none
    if (t.corner_chamfer) t.corner_radius.reset();
    read("diameter", t.profile_diameter);
  }
  if (j.contains("operations") && j["operations"].is_array()) {
    for (const auto& o : j["operations"]) t.operations.push_back(read_operation(o, file, t.id));
  } else if (j.contains("machined_by") && j["machined_by"].is_array()) {
    std::vector<std::pair<std::string, std::string>> ops;
    std::vector<int> tools;
    for (const auto& o : j["machined_by"]) {
      ops.emplace_back(o.value("op_type", std::string{}), o.value("strategy", std::string{}));
      tools.push_back(o.value("tool_number", 0));
    }
    t.operations = freecad_operations(ops, tools, t.type, file, t.id);
  }
  switch (t.type) {
    case FeatureType::RoundHole:
    case FeatureType::ClosedPocket: t.closed = true; break;
    case FeatureType::Slot: {
      bool open = j.value("shape", std::string{}).find("through") != std::string::npos;
      if (j.contains("end_conditions")) {
        for (const auto& e : j["end_conditions"]) open = open || e.get<std::string>() == "open";
      }
      t.closed = !open;
      break;
    }
    default: t.closed = false;
  }
  return t;
}

}  // namespace

std::vector<TruthOperation> freecad_operations(const std::vector<std::pair<std::string, std::string>>& op_type_and_strategy,
                                               const std::vector<int>& tool_numbers, FeatureType type,
                                               const std::string& file, const std::string& id) {
  std::vector<TruthOperation> out;
  const std::size_t count = op_type_and_strategy.size();
  for (std::size_t k = 0; k < count; ++k) {
    const auto& [op_type, text] = op_type_and_strategy[k];
    TruthOperation op;
    op.tool_number = k < tool_numbers.size() ? tool_numbers[k] : 0;
    op.source = op_type + " " + text;
    // A FreeCAD operation states no roughing or finishing: one operation alone finishes a face
    // or an outside profile (it makes the final surface) and roughs anything else; of several on
    // one feature the last finishes. The same rule the recogniser names its operations by.
    const bool finishing = k + 1 == count && (count > 1 || type == FeatureType::PlanarFace ||
                                              type == FeatureType::GeneralOutsideProfile);
    if (op_type == "ObjectDrilling") {
      op.type = text.find("G83") != std::string::npos || text.find("G73") != std::string::npos
                    ? OperationType::MultistepDrilling
                    : text.find("G85") != std::string::npos ? OperationType::Reaming : OperationType::Drilling;
      op.strategies = {Strategy::Plunge};
    } else if (op_type == "ObjectHelix") {
      op.type = milling_type(type, finishing);
      op.strategies = {Strategy::Helical};
    } else if (op_type == "ObjectProfile") {
      op.type = milling_type(type, finishing);
      op.strategies = {Strategy::Contour};
    } else if (op_type == "ObjectSlot") {
      op.type = milling_type(type, finishing);
      op.strategies = {Strategy::CenterMilling};
    } else if (op_type == "PathAdaptive") {
      op.type = milling_type(type, finishing);
      op.strategies = {Strategy::Adaptive};
    } else if (op_type == "ObjectFace" || op_type == "ObjectPocket") {
      op.type = milling_type(type, finishing);
      // The clearing pattern, the first word of the text.
      if (starts_with(text, "ZigZagOffset")) {
        op.strategies = {Strategy::BidirectionalContour, Strategy::ContourBidirectional};
      } else if (starts_with(text, "ZigZag")) {
        op.strategies = {Strategy::Bidirectional};
      } else if (starts_with(text, "Offset")) {
        op.strategies = {Strategy::ContourParallel};
      } else if (starts_with(text, "Line")) {
        op.strategies = {Strategy::Unidirectional};
      } else if (starts_with(text, "Spiral")) {
        op.strategies = {Strategy::ContourSpiral};
      } else {
        throw InputError({file, 0, 0}, "feature '" + id + "': FreeCAD pattern '" + text + "' has no ISO 14649 strategy here");
      }
    } else {
      throw InputError({file, 0, 0}, "feature '" + id + "': FreeCAD operation '" + op_type + "' is not mapped to ISO 14649");
    }
    out.push_back(std::move(op));
  }
  return out;
}

std::vector<TruthFeature> read_truth(const std::filesystem::path& file, const std::string& program) {
  std::ifstream in(file);
  if (!in) throw InputError({file.string(), 0, 0}, "cannot open the truth file");
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError({file.string(), 0, 0}, std::string("not valid JSON: ") + e.what());
  }
  const nlohmann::json* list = nullptr;
  if (!program.empty()) {
    if (!root.contains(program) || !root[program].contains("features")) {
      throw InputError({file.string(), 0, 0}, "no features for program '" + program + "'");
    }
    list = &root[program]["features"];
  } else {
    if (!root.contains("features")) throw InputError({file.string(), 0, 0}, "no \"features\" list");
    list = &root["features"];
  }
  std::vector<TruthFeature> out;
  try {
    for (const auto& j : *list) out.push_back(read_feature(j, file.string()));
  } catch (const nlohmann::json::exception& e) {
    throw InputError({file.string(), 0, 0}, std::string("malformed feature: ") + e.what());
  }
  return out;
}

double TypeScore::precision() const { return recognized > 0 ? static_cast<double>(matched) / recognized : (truth == 0 ? 1 : 0); }
double TypeScore::recall() const { return truth > 0 ? static_cast<double>(matched) / truth : (recognized == 0 ? 1 : 0); }
double TypeScore::f1() const {
  const double p = precision(), r = recall();
  return p + r > 0 ? 2 * p * r / (p + r) : 0;
}

double Score::mean_position_error() const {
  if (matches.empty()) return 0;
  double sum = 0;
  for (const auto& m : matches) sum += m.position_error;
  return sum / static_cast<double>(matches.size());
}

Score score(const std::vector<RecognizedFeature>& recognized, const std::vector<TruthFeature>& truth) {
  Score s;
  for (const auto& t : truth) ++s.per_type[t.type].truth;
  for (const auto& r : recognized) ++s.per_type[r.type].recognized;

  struct Candidate {
    double error;
    std::size_t t, r;
  };
  std::vector<Candidate> candidates;
  for (std::size_t ti = 0; ti < truth.size(); ++ti) {
    const auto& t = truth[ti];
    for (std::size_t ri = 0; ri < recognized.size(); ++ri) {
      const auto& r = recognized[ri];
      if (r.type != t.type) continue;
      const double error = std::hypot(r.x - t.x, r.y - t.y);
      if (error > (t.closed ? 1.0 : 5.0)) continue;
      if (std::abs(r.top_z - t.top_z) > 0.2 || std::abs(r.bottom_z - t.bottom_z) > 0.2) continue;
      if (t.diameter && std::abs(r.diameter - *t.diameter) > 0.05) continue;
      candidates.push_back({error, ti, ri});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.error < b.error; });
  std::vector<bool> t_used(truth.size()), r_used(recognized.size());
  for (const auto& c : candidates) {
    if (t_used[c.t] || r_used[c.r]) continue;
    t_used[c.t] = r_used[c.r] = true;
    s.matches.push_back({c.t, c.r, c.error});
    ++s.per_type[truth[c.t].type].matched;
  }
  for (const auto& [type, ts] : s.per_type) {
    s.overall.truth += ts.truth;
    s.overall.recognized += ts.recognized;
    s.overall.matched += ts.matched;
  }
  return s;
}

TypeScore score_operations(const std::vector<RecognizedFeature>& recognized, const std::vector<TruthFeature>& truth,
                           const Score& features) {
  TypeScore out;
  for (const auto& m : features.matches) {
    const auto& t = truth[m.truth_index].operations;
    if (t.empty()) continue;
    const auto& r = recognized[m.recognized_index].operations;
    out.truth += static_cast<int>(t.size());
    out.recognized += static_cast<int>(r.size());
    std::size_t next = 0;  // in order: a matched recognised operation is not reused
    for (const auto& want : t) {
      for (std::size_t k = next; k < r.size(); ++k) {
        if (r[k].type == want.type && r[k].tool_number == want.tool_number &&
            (want.strategies.empty() ||
             std::find(want.strategies.begin(), want.strategies.end(), r[k].strategy) != want.strategies.end())) {
          ++out.matched;
          next = k + 1;
          break;
        }
      }
    }
  }
  return out;
}

}  // namespace ncbridge::feature_recognizer
