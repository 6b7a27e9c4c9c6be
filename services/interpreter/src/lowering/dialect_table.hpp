#pragma once
// A dialect's dictionary (services/interpreter/dialects/<dialect>.yaml, embedded in the library
// at build time): what each G/M code means in the meta-model, the neutral RS274 code it lowers
// to when it maps one to one, and the cycle parameter maps. Read once per interpretation.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ncbridge::interpreter::lowering {

struct CodeEntry {
  std::string meta;               // meta-model activity, e.g. "rapid", "polar_on"
  std::optional<double> rs274;    // neutral code, when the activity is one RS274 code
  std::optional<int> cycle;       // canned cycle number (Fanuc/Mach G73..G89)
};

struct CycleEntry {
  std::string name;                               // the controller's name for it
  std::string meta;
  std::map<std::string, std::string> roles;       // word / Q number / line number -> role
  std::vector<std::string> positional;            // Siemens: parameter names in call order
  std::vector<std::string> required;              // parameters a definition must give
};

struct DialectTable {
  std::string dialect;
  std::map<std::string, double> settings;
  std::map<std::string, CodeEntry> g_codes;       // key: code as written in the table ("90.1")
  std::map<std::string, CodeEntry> m_codes;
  std::map<std::string, std::map<std::string, std::string>> cycle_words;  // cycle -> word -> role
  std::map<std::string, CycleEntry> cycles;
  std::map<std::string, CycleEntry> patterns;     // Siemens HOLES1/HOLES2
  std::map<std::string, CycleEntry> milling_cycles;  // Siemens POCKET3/POCKET4
  std::map<std::string, CodeEntry> path_functions;
  std::map<std::string, CodeEntry> radius_compensation;
  std::vector<std::string> unsupported_cycles;
  std::vector<std::string> ignored_calls;
  // M codes the machine builder gives machine functions (clamps, pallet, chip conveyor, probe
  // power): code -> what it does. Read with a warning; they move nothing.
  std::map<std::string, std::string> machine_functions;

  const CodeEntry* g(double code) const;
  const CodeEntry* m(double code) const;
  double setting(const std::string& name, double fallback) const;
};

// The embedded table of `dialect` ("fanuc", "mach3", "siemens840d", "heidenhain").
DialectTable load_dialect_table(const std::string& dialect);
// Parses table text (used by load_dialect_table and by tests of the tables themselves).
DialectTable parse_dialect_table(const std::string& yaml_text, const std::string& name);

// Key of a code value in the tables: "0", "16", "90.1".
std::string code_key(double code);

}  // namespace ncbridge::interpreter::lowering
