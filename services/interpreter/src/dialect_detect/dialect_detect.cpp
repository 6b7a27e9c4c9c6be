// Dialect detection by syntax: each dialect has constructs no other dialect writes; the first
// decisive one wins, and the reason names it with its line.
#include "ncbridge/interpreter/dialect_detect.hpp"

#include <fstream>
#include <regex>
#include <vector>

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter {

namespace {

std::string upper_copy(std::string_view s) {
  std::string r(s);
  for (char& c : r) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return r;
}

struct Rule {
  Dialect dialect;
  const char* what;
  std::regex pattern;
};

const std::vector<Rule>& rules() {
  // Decisive constructs, strongest first. Post-processor names in header comments come first:
  // they say what the program was written for.
  static const std::vector<Rule> kRules = [] {
    auto r = [](Dialect d, const char* what, const char* re) { return Rule{d, what, std::regex(re, std::regex::optimize)}; };
    return std::vector<Rule>{
        r(Dialect::Heidenhain, "BEGIN PGM", R"(^\s*\d*\s*BEGIN\s+PGM\b)"),
        r(Dialect::Heidenhain, "TOOL CALL", R"(^\s*\d*\s*TOOL\s+CALL\b)"),
        r(Dialect::Heidenhain, "CYCL DEF", R"(^\s*\d*\s*CYCL\s+DEF\b)"),
        r(Dialect::Heidenhain, "an L block with signed coordinates", R"(^\s*\d+\s+L\s+[XYZ][+-])"),
        r(Dialect::Mach3, "a Mach3/Mach4 post-processor header", R"(MACH3|MACH4|MACH 3)"),
        r(Dialect::Fanuc, "a Fanuc post-processor header", R"(\(.*FANUC)"),
        r(Dialect::Rs274Ngc, "a LinuxCNC post-processor header", R"(\(.*(LINUXCNC|EMC2))"),
        // CAM systems whose usual output is for Mach3: pcb-gcode's Mach3 profile, CamBam's
        // default post, Vectric's Mach2/3 posts, Estlcam (after the controller names above, which
        // say more)
        r(Dialect::Mach3, "a pcb-gcode, CamBam, Vectric or Estlcam header (their posts for Mach3)",
          R"((\(|;).*(PCB-GCODE|PCB GCODE|CAMBAM|VECTRIC|ESTLCAM))"),
        r(Dialect::Rs274Ngc, "an o-word statement", R"(^\s*(N\d+\s*)?O\s*(<[^>]*>|\d+)\s*(SUB|ENDSUB|CALL|IF|ELSE|ENDIF|WHILE|ENDWHILE|DO|REPEAT|ENDREPEAT|RETURN)\b)"),
        r(Dialect::Rs274Ngc, "a named parameter #<...>", R"(#<)"),
        r(Dialect::Siemens840D, "T=\"name\"", R"(\bT\s*=\s*")"),
        r(Dialect::Siemens840D, "a SINUMERIK cycle call", R"(\b(CYCLE\d{2,3}|POCKET\d|SLOT\d|LONGHOLE|HOLES\d)\s*\()"),
        r(Dialect::Siemens840D, "a DEF declaration", R"(^\s*(N\d+\s*)?DEF\s+(REAL|INT|BOOL|CHAR|STRING|AXIS|FRAME)\b)"),
        r(Dialect::Siemens840D, "a frame instruction", R"(\b(TRANS|ATRANS|AROT|SUPA|TRAFOOF|G500|G710|G700)\b)"),
        r(Dialect::Siemens840D, "an R parameter assignment", R"(\bR\d+\s*=)"),
        r(Dialect::Siemens840D, "GOTOF/GOTOB", R"(\bGOTO[FB]\b)"),
        r(Dialect::Siemens840D, "a program end M17 or MSG()", R"(\bM17\b|\bMSG\s*\()"),
        r(Dialect::Fanuc, "a macro B statement", R"(\b(IF\s*\[|WHILE\s*\[|GOTO\s*\d|END\s*[123]\b)|#\d+\s*=)"),
        r(Dialect::Fanuc, "an O program number", R"(^\s*O\d+\b)"),
        r(Dialect::Fanuc, "M98 P", R"(\bM98\s*P)"),
        r(Dialect::Fanuc, "G65 macro call", R"(\bG65\b)"),
        // Vectric's Mach2/3 post: the tool change alone and packed (T1M6), positions packed
        // without blanks (G0X0.000Y0.000S15000M3)
        r(Dialect::Mach3, "the layout of Vectric's Mach2/3 post (T1M6 alone, packed words)", R"(^T\d+M0?6\s*$)"),
    };
  }();
  return kRules;
}

}  // namespace

DetectedDialect detect_dialect(std::string_view text) {
  if (text.size() > 65536) text = text.substr(0, 65536);
  std::vector<std::string> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    lines.push_back(upper_copy(text.substr(begin, end - begin)));
    begin = end + 1;
  }
  for (const Rule& rule : rules()) {
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (std::regex_search(lines[i], rule.pattern)) {
        return {rule.dialect, std::string(rule.what) + ", line " + std::to_string(i + 1), true};
      }
    }
  }
  return {Dialect::Rs274Ngc, "no dialect-specific syntax found: RS274/NGC assumed"};
}

DetectedDialect detect_dialect_file(const std::filesystem::path& program) {
  std::ifstream in(program, std::ios::binary);
  if (!in) throw InputError({program.string(), 0, 0}, "cannot open program file");
  std::string text(65536, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return detect_dialect(text);
}

std::string_view dialect_name(Dialect dialect) {
  switch (dialect) {
    case Dialect::Rs274Ngc: return "rs274ngc";
    case Dialect::Fanuc: return "fanuc";
    case Dialect::Mach3: return "mach3";
    case Dialect::Siemens840D: return "siemens840d";
    case Dialect::Heidenhain: return "heidenhain";
    case Dialect::Auto: return "auto";
  }
  return "rs274ngc";
}

bool parse_dialect_name(std::string_view name, Dialect& dialect) {
  for (Dialect d : {Dialect::Rs274Ngc, Dialect::Fanuc, Dialect::Mach3, Dialect::Siemens840D, Dialect::Heidenhain,
                    Dialect::Auto}) {
    if (dialect_name(d) == name) {
      dialect = d;
      return true;
    }
  }
  return false;
}

}  // namespace ncbridge::interpreter
