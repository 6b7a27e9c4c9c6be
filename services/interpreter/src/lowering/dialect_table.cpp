#include "lowering/dialect_table.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <stdexcept>

#include "lowering/embedded_tables.hpp"

namespace ncbridge::interpreter::lowering {

std::string code_key(double code) {
  if (!(std::fabs(code) < 1e6)) return "?";  // no table has such a code (and NaN is none)
  double tenths = std::nearbyint(code * 10.0);
  long whole = static_cast<long>(tenths) / 10;
  long fraction = static_cast<long>(tenths) % 10;
  std::string key = std::to_string(whole);
  if (fraction != 0) key += "." + std::to_string(fraction < 0 ? -fraction : fraction);
  return key;
}

const CodeEntry* DialectTable::g(double code) const {
  auto it = g_codes.find(code_key(code));
  return it == g_codes.end() ? nullptr : &it->second;
}

const CodeEntry* DialectTable::m(double code) const {
  auto it = m_codes.find(code_key(code));
  return it == m_codes.end() ? nullptr : &it->second;
}

double DialectTable::setting(const std::string& name, double fallback) const {
  auto it = settings.find(name);
  return it == settings.end() ? fallback : it->second;
}

namespace {

std::map<std::string, CodeEntry> read_codes(const YAML::Node& node) {
  std::map<std::string, CodeEntry> codes;
  if (!node) return codes;
  for (const auto& kv : node) {
    CodeEntry e;
    e.meta = kv.second["meta"].as<std::string>();
    if (kv.second["rs274"]) e.rs274 = kv.second["rs274"].as<double>();
    if (kv.second["cycle"]) e.cycle = kv.second["cycle"].as<int>();
    codes.emplace(kv.first.as<std::string>(), e);
  }
  return codes;
}

}  // namespace

DialectTable parse_dialect_table(const std::string& yaml_text, const std::string& name) {
  DialectTable t;
  try {
    YAML::Node root = YAML::Load(yaml_text);
    t.dialect = root["dialect"].as<std::string>();
    if (root["settings"]) {
      for (const auto& kv : root["settings"]) t.settings[kv.first.as<std::string>()] = kv.second.as<double>();
    }
    t.g_codes = read_codes(root["g_codes"]);
    t.m_codes = read_codes(root["m_codes"]);
    t.path_functions = read_codes(root["path_functions"]);
    t.radius_compensation = read_codes(root["radius_compensation"]);
    if (root["cycle_words"]) {
      for (const auto& cycle : root["cycle_words"]) {
        auto& words = t.cycle_words[cycle.first.as<std::string>()];
        for (const auto& kv : cycle.second) words[kv.first.as<std::string>()] = kv.second.as<std::string>();
      }
    }
    for (const char* section : {"cycles", "patterns", "milling_cycles"}) {
      if (!root[section]) continue;
      const std::string which = section;
      auto& target = which == "cycles" ? t.cycles : which == "patterns" ? t.patterns : t.milling_cycles;
      for (const auto& cycle : root[section]) {
        CycleEntry e;
        const YAML::Node& c = cycle.second;
        if (c["name"]) e.name = c["name"].as<std::string>();
        if (c["meta"]) e.meta = c["meta"].as<std::string>();
        for (const char* key : {"parameters", "lines"}) {
          const YAML::Node& p = c[key];
          if (!p) continue;
          if (p.IsSequence()) {
            for (const auto& item : p) e.positional.push_back(item.as<std::string>());
          } else {
            for (const auto& kv : p) e.roles[kv.first.as<std::string>()] = kv.second.as<std::string>();
          }
        }
        if (c["required"]) {
          for (const auto& item : c["required"]) e.required.push_back(item.as<std::string>());
        }
        target.emplace(cycle.first.as<std::string>(), std::move(e));
      }
    }
    for (const char* key : {"unsupported_cycles", "ignored_calls"}) {
      auto& list = std::string(key) == "unsupported_cycles" ? t.unsupported_cycles : t.ignored_calls;
      if (root[key]) {
        for (const auto& item : root[key]) list.push_back(item.as<std::string>());
      }
    }
    if (root["machine_functions"]) {
      for (const auto& kv : root["machine_functions"]) {
        t.machine_functions[kv.first.as<std::string>()] = kv.second.as<std::string>();
      }
    }
  } catch (const YAML::Exception& e) {
    throw std::logic_error("dialect table " + name + " is malformed: " + e.what());
  }
  return t;
}

DialectTable load_dialect_table(const std::string& dialect) {
  std::string_view text = embedded_dialect_table(dialect);
  if (text.empty()) throw std::logic_error("no embedded dialect table named " + dialect);
  return parse_dialect_table(std::string(text), dialect + ".yaml");
}

}  // namespace ncbridge::interpreter::lowering
