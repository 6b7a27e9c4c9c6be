#include "ncbridge/part_reader/brep_reader.hpp"

#include <chrono>
#include <cmath>
#include <fstream>

#include "brep_extract.hpp"
#include "brep_recognize.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/part_reader/ap224_reader.hpp"
#include "ncbridge/part_reader/setup_frame.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"

namespace ncbridge::part_reader {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// The first name of FILE_SCHEMA and whether the file starts like a Part 21 file, from its head.
struct Head {
  bool part21 = false;
  std::string schema;
};

Head head_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path.string(), 0, 0}, "cannot open the file");
  std::string text(65536, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  Head h;
  std::size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  h.part21 = text.compare(i, 13, "ISO-10303-21;") == 0;
  const std::string u = upper(text);
  const auto at = u.find("FILE_SCHEMA");
  if (at != std::string::npos) {
    const auto quote = u.find('\'', at);
    const auto end = quote == std::string::npos ? std::string::npos : u.find('\'', quote + 1);
    if (end != std::string::npos) h.schema = u.substr(quote + 1, end - quote - 1);
  }
  return h;
}

std::string format_of(const std::string& schema) {
  if (schema.find("CONFIG_CONTROL_DESIGN") != std::string::npos) return "AP203";
  if (schema.find("AUTOMOTIVE_DESIGN") != std::string::npos) return "AP214";
  if (schema.find("AP242") != std::string::npos || schema.find("MODEL_BASED_3D") != std::string::npos) return "AP242";
  if (schema.find("AP203") != std::string::npos) return "AP203";
  return schema.empty() ? "STEP" : schema.substr(0, schema.find(' '));
}

}  // namespace

Part read_brep_file(const std::filesystem::path& path, const ReadOptions& options, BrepTimings* timings) {
  using Clock = std::chrono::steady_clock;
  const SetupFrame frame(options);
  const auto t0 = Clock::now();
  double occt_ms = 0;
  const brep::Model model = brep::load_step(path, frame, &occt_ms);
  const auto t1 = Clock::now();
  brep::Recognized r;
  r.used.assign(model.faces.size(), 0);
  brep::recognize_footprint(model, r);
  brep::recognize_holes(model, r);
  brep::recognize_floors(model, r);
  brep::report_other_faces(model, r);
  if (timings) {
    timings->occt_ms = occt_ms;
    timings->model_ms = std::chrono::duration<double, std::milli>(t1 - t0).count() - occt_ms;
    timings->recognition_ms = std::chrono::duration<double, std::milli>(Clock::now() - t1).count();
  }

  Part part;
  part.file = path.string();
  part.name = path.stem().string();
  part.format = format_of(head_of(path).schema);
  part.file_units = model.file_units;
  part.bounds = Box{{model.box_min.x, model.box_min.y, model.box_min.z}, {model.box_max.x, model.box_max.y, model.box_max.z}};
  part.footprint = std::move(r.footprint);
  part.top_z = r.top_z;
  part.bottom_z = r.bottom_z;
  part.compounds = std::move(r.compounds);
  part.warnings = std::move(r.warnings);
  for (auto& f : r.features) {
    f.accessible = std::abs(f.placement.axis.z - 1) < 1e-6;
    if (!f.accessible) {
      std::string kind(to_string(f.kind));
      for (char& c : kind) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      part.warnings.push_back({f.source, kind + ": " + needed_setup_text(frame.to_part(f.placement.axis)) + "; not planned"});
    }
  }
  part.features = std::move(r.features);
  return part;
}

Box read_step_box(const std::filesystem::path& path) { return brep::step_box(path); }

Part read_part_file(const std::filesystem::path& path, const ReadOptions& options) {
  const Head head = head_of(path);
  if (!head.part21 || head.schema.find("FEATURE_BASED_PROCESS_PLANNING") != std::string::npos) {
    return read_ap224_file(path, options);  // the project's reader says where a non-STEP file goes wrong
  }
  try {
    return read_brep_file(path, options);
  } catch (const InputError&) {
    step_writer::part21::read_part21_file(path);  // a syntax error, located
    throw;
  }
}

}  // namespace ncbridge::part_reader
