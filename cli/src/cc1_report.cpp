// Streamed CC1 report: the JSON text is made by hand, one line per workplan element and per
// feature, and handed to the atomic file in pieces of about 1 MB. The features come after the
// whole workplan in the report, so they wait in an anonymous temporary file.
#include "cc1_report.hpp"

#include "ncbridge/common/version.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <system_error>

namespace ncbridge::cli {

namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

void append_string(std::string& out, std::string_view s) {
  out += '"';
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          static constexpr char kHex[] = "0123456789abcdef";
          out += "\\u00";
          out += kHex[(c >> 4) & 0xF];
          out += kHex[c & 0xF];
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

// Shortest round-trip text, with ".0" on integral values as nlohmann::json writes them.
void append_number(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  const std::string_view text(buf, static_cast<std::size_t>(end - buf));
  out += text;
  if (text.find_first_of(".e") == std::string_view::npos) out += ".0";
}

void append_key(std::string& out, std::string_view key) {
  append_string(out, key);
  out += ": ";
}

}  // namespace

Cc1Report::Cc1Report(OutputFile& out, const Head& head) : file_(out), features_(std::tmpfile()) {
  if (features_ == nullptr) throw std::system_error(errno, std::generic_category(), "report: temporary file");
  text_ = "{\n  ";
  append_key(text_, "ncbridge_version");
  append_string(text_, version());
  text_ += ",\n  ";
  append_key(text_, "program");
  append_string(text_, head.program);
  text_ += ",\n  ";
  append_key(text_, "output");
  append_string(text_, head.output);
  text_ += ",\n  ";
  append_key(text_, "level");
  append_string(text_, head.level);
  text_ += ",\n  \"workingsteps\": [";
}

Cc1Report::~Cc1Report() { std::fclose(features_); }

void Cc1Report::element(const stepnc::Project& project, const stepnc::Executable& element) {
  text_ += first_element_ ? "\n    {" : ",\n    {";
  first_element_ = false;
  const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&element);
  append_key(text_, "kind");
  append_string(text_, ws ? "MACHINING_WORKINGSTEP"
                          : std::holds_alternative<stepnc::WorkpieceProbing>(element) ? "WORKPIECE_PROBING"
                                                                                       : "RAPID_MOVEMENT");
  std::visit(
      [&](const auto& x) {
        text_ += ", ";
        append_key(text_, "id");
        append_string(text_, x.its_id);
        if (x.source.first_line != 0) {
          text_ += ", \"lines\": [" + std::to_string(x.source.first_line) + ", " + std::to_string(x.source.last_line) + "]";
        }
      },
      element);
  if (ws) {
    const auto& op = project.operation(ws->its_operation);
    const auto& mop = stepnc::machining_operation(op);
    const auto& feature = project.feature(ws->its_feature);
    text_ += ", ";
    append_key(text_, "operation");
    append_string(text_, stepnc::entity_name(op));
    text_ += ", ";
    append_key(text_, "feature");
    append_string(text_, stepnc::feature_id(feature));
    text_ += ", ";
    append_key(text_, "tool");
    append_string(text_, project.tool(mop.its_tool).its_id);
    const auto& t = project.technology(mop.its_technology);
    if (t.feedrate) {
      text_ += ", ";
      append_key(text_, "feedrate_m_per_s");
      append_number(text_, *t.feedrate);
    }
    if (t.spindle) {
      text_ += ", ";
      append_key(text_, "spindle_rev_per_s");
      append_number(text_, *t.spindle);
    }
    feature_text_ += first_feature_ ? "\n    {" : ",\n    {";
    first_feature_ = false;
    append_key(feature_text_, "id");
    append_string(feature_text_, stepnc::feature_id(feature));
    feature_text_ += ", ";
    append_key(feature_text_, "type");
    append_string(feature_text_, stepnc::entity_name(feature));
    feature_text_ += '}';
    if (feature_text_.size() >= kFlushBytes) flush_features();
  }
  text_ += '}';
  if (text_.size() >= kFlushBytes) flush_text();
}

void Cc1Report::flush_text() {
  file_.write(text_);
  text_.clear();
}

void Cc1Report::flush_features() {
  if (!feature_text_.empty() && std::fwrite(feature_text_.data(), 1, feature_text_.size(), features_) != feature_text_.size()) {
    throw std::system_error(errno, std::generic_category(), "report: temporary file");
  }
  feature_text_.clear();
}

void Cc1Report::finish(const stepnc::Project& project, const Tail& tail) {
  text_ += first_element_ ? "],\n  " : "\n  ],\n  ";
  text_ += "\"features\": [";
  flush_text();
  flush_features();
  std::rewind(features_);
  std::string chunk(kFlushBytes, '\0');
  for (std::size_t n; (n = std::fread(chunk.data(), 1, chunk.size(), features_)) > 0;) file_.write(std::string_view(chunk.data(), n));
  if (std::ferror(features_)) throw std::system_error(errno, std::generic_category(), "report: temporary file");
  text_ += first_feature_ ? "],\n  " : "\n  ],\n  ";

  append_key(text_, "canonical_calls");
  text_ += std::to_string(tail.canonical_calls);
  text_ += ",\n  ";
  append_key(text_, "output_bytes");
  text_ += std::to_string(tail.output_bytes);
  text_ += ",\n  \"tools\": [";
  for (std::size_t i = 0; i < project.tools.size(); ++i) {
    const auto& t = project.tools[i];
    text_ += i == 0 ? "\n    {" : ",\n    {";
    append_key(text_, "number");
    text_ += std::to_string(t.number);
    text_ += ", ";
    append_key(text_, "id");
    append_string(text_, t.its_id);
    text_ += ", ";
    append_key(text_, "diameter_mm");
    append_number(text_, t.dimension.diameter);
    text_ += '}';
  }
  text_ += project.tools.empty() ? "],\n  " : "\n  ],\n  ";
  text_ += "\"warnings\": [";
  for (std::size_t i = 0; i < tail.warnings.size(); ++i) {
    text_ += i == 0 ? "\n    {" : ",\n    {";
    append_key(text_, "kind");
    append_string(text_, tail.warnings[i].kind);
    text_ += ", ";
    append_key(text_, "where");
    append_string(text_, tail.warnings[i].where.to_string());
    text_ += ", ";
    append_key(text_, "message");
    append_string(text_, tail.warnings[i].message);
    text_ += '}';
  }
  text_ += tail.warnings.empty() ? "],\n  " : "\n  ],\n  ";
  text_ += "\"timings_ms\": {";
  for (std::size_t i = 0; i < tail.timings_ms.size(); ++i) {
    text_ += i == 0 ? "\n    " : ",\n    ";
    append_key(text_, tail.timings_ms[i].first);
    append_number(text_, tail.timings_ms[i].second);
  }
  text_ += tail.timings_ms.empty() ? "}\n}\n" : "\n  }\n}\n";
  flush_text();
}

}  // namespace ncbridge::cli
