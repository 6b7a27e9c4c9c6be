#pragma once
// A dialect program held in memory as lines. The label-and-jump dialects (Fanuc GOTO n,
// Siemens GOTOF/GOTOB, Heidenhain LBL) search the whole program for their targets, and
// subprograms may sit anywhere in it, so their front-ends keep the text; programs are read
// once and never copied.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::interpreter::lowering {

struct ProgramText {
  std::string name;                      // as the user named it, for messages
  std::string text;
  struct Span { std::size_t begin, length; };
  std::vector<Span> spans;               // line i+1 is spans[i], without its terminator

  std::size_t size() const { return spans.size(); }
  std::string_view line(std::size_t index) const {
    return std::string_view(text).substr(spans[index].begin, spans[index].length);
  }

  static ProgramText from_text(std::string text, std::string name);
  // Throws InputError when the file cannot be read.
  static ProgramText from_file(const std::filesystem::path& path);
};

}  // namespace ncbridge::interpreter::lowering
