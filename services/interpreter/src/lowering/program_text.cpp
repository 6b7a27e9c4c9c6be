#include "lowering/program_text.hpp"

#include <fstream>
#include <sstream>

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::lowering {

ProgramText ProgramText::from_text(std::string text, std::string name) {
  ProgramText p;
  p.name = std::move(name);
  p.text = std::move(text);
  std::string_view all(p.text);
  std::size_t begin = 0;
  while (begin < all.size()) {
    std::size_t end = all.find('\n', begin);
    if (end == std::string_view::npos) end = all.size();
    std::size_t length = end - begin;
    if (length > 0 && all[end - 1] == '\r') --length;
    p.spans.push_back({begin, length});
    begin = end + 1;
  }
  return p;
}

ProgramText ProgramText::from_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path.string(), 0, 0}, "cannot open program file");
  std::ostringstream text;
  text << in.rdbuf();
  return from_text(text.str(), path.string());
}

}  // namespace ncbridge::interpreter::lowering
