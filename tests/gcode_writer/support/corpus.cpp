#include "corpus.hpp"

#include <algorithm>
#include <fstream>

#include "ncbridge/setup/tool_list.hpp"
#include "support/golden_cases.hpp"

namespace fs = std::filesystem;

namespace ncbridge::testing {

namespace {

const fs::path kSource = NCBRIDGE_SOURCE_DIR;
const fs::path kShared = NCBRIDGE_SHARED_DIR;

interpreter::Dialect dialect_of_extension(const fs::path& file) {
  const std::string e = file.extension().string();
  if (e == ".nc") return interpreter::Dialect::Fanuc;
  if (e == ".tap") return interpreter::Dialect::Mach3;
  if (e == ".mpf" || e == ".MPF") return interpreter::Dialect::Siemens840D;
  if (e == ".h" || e == ".H") return interpreter::Dialect::Heidenhain;
  return interpreter::Dialect::Rs274Ngc;
}

std::vector<fs::path> sorted_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool starts_fanuc_post(const fs::path& file) {
  std::ifstream in(file);
  std::string head(600, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  return head.find("FANUC") != std::string::npos || head.find("fanuc") != std::string::npos;
}

}  // namespace

std::vector<CorpusProgram> corpus_programs() {
  std::vector<CorpusProgram> out;
  const fs::path golden = kSource / "tests/interpreter/golden";
  for (const GoldenCase& g : read_golden_cases(golden, kShared)) {
    CorpusProgram p;
    p.name = "golden/" + g.name;
    p.program = g.program;
    p.tools = g.tools_file;
    p.tools_kind = g.tools_kind;
    p.rs274_tool_table = g.rs274_tool_table;
    if (!g.subroutine_path.empty()) p.subroutine_path.push_back(g.subroutine_path);
    out.push_back(p);
  }
  const fs::path dialects = kSource / "tests/interpreter/dialects";
  const fs::path part_tools = dialects / "parts/tools.json";
  const fs::path part_rs274_tools = dialects / "parts/tools.rs274.tbl";
  for (const char* part : {"plate", "bolt_circle", "macro_pocket"}) {
    for (const fs::path& f : sorted_files(dialects / "parts" / part)) {
      if (f.filename().string().rfind("part", 0) != 0) continue;
      out.push_back({"dialects/parts/" + std::string(part) + "/" + f.filename().string(), f, dialect_of_extension(f),
                     part_tools, "tools-json", part_rs274_tools, {}, false});
    }
  }
  for (const char* d : {"fanuc", "mach3", "siemens840d", "heidenhain"}) {
    for (const fs::path& f : sorted_files(dialects / d)) {
      const interpreter::Dialect dialect =
          f.extension() == ".ngc" ? interpreter::Dialect::Rs274Ngc : dialect_of_extension(f);
      out.push_back({"dialects/" + std::string(d) + "/" + f.filename().string(), f, dialect, part_tools, "tools-json",
                     part_rs274_tools, {}, false});
    }
  }
  for (const auto& entry : fs::directory_iterator(kShared / "corpus/cam")) {
    if (!entry.is_directory()) continue;
    const fs::path dir = entry.path();
    const std::string part = dir.filename().string();
    for (const fs::path& f : sorted_files(dir)) {
      const std::string file = f.filename().string();
      if (file.rfind("part.", 0) != 0 || f.extension() == ".step") continue;
      CorpusProgram p{"cam/" + part + "/" + file, f, interpreter::Dialect::Rs274Ngc, dir / "tools.json", "tools-json",
                      golden / "tools" / ("cam_" + part + ".rs274.tbl"), {}, false};
      if (f.extension() == ".h") {
        p.dialect = interpreter::Dialect::Heidenhain;
        p.feed_per_second = true;
      } else if (file.find("fanuc") != std::string::npos || (file == "part.nc" && starts_fanuc_post(f))) {
        p.dialect = interpreter::Dialect::Fanuc;
      } else if (f.extension() == ".tap") {
        p.dialect = interpreter::Dialect::Mach3;
      }
      out.push_back(p);
    }
  }
  for (const char* f : {"face_mill.ngc", "test_part.ngc"}) {
    out.push_back({std::string("paper/") + f, kShared / "corpus/paper" / f, interpreter::Dialect::Rs274Ngc,
                   kShared / "corpus/paper/tools.json", "tools-json", golden / "tools/paper.rs274.tbl", {}, false});
  }
  out.push_back({"examples/plate", kSource / "examples/plate/plate.ngc", interpreter::Dialect::Rs274Ngc,
                 kSource / "examples/plate/tools.json", "tools-json", kSource / "examples/plate/tools.tbl", {}, false});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

interpreter::Options reading_options(const CorpusProgram& p) {
  interpreter::Options o;
  o.dialect = p.dialect;
  if (p.tools_kind == "tools-json") {
    o.tools = setup::read_tool_list(p.tools);
  } else if (!p.tools.empty()) {
    o.tools = setup::read_linuxcnc_tool_table(
        p.tools, p.tools_kind == "tool-table-inch" ? setup::LengthUnits::Inches : setup::LengthUnits::Millimeters);
  }
  o.subroutine_path = p.subroutine_path;
  if (p.feed_per_second) o.heidenhain_feed_units = interpreter::Options::FeedUnits::PerSecond;
  return o;
}

std::string test_name(std::string_view text) {
  std::string s;
  for (char c : text) s.push_back(std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  return s;
}

}  // namespace ncbridge::testing
