#include "input_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "errors.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::cli {

namespace {

std::string read_standard_input() {
  std::string text;
  char chunk[1 << 16];
  for (;;) {
    const ssize_t n = ::read(STDIN_FILENO, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError({"<stdin>", 0, 0}, std::string("cannot read standard input: ") + std::strerror(errno));
    if (n == 0) return text;
    text.append(chunk, static_cast<std::size_t>(n));
  }
}

}  // namespace

void require_input_file(const std::string& path, std::string_view what) {
  const std::string suffix = " (" + std::string(what) + ")";
  if (path == "-") throw UsageError(std::string(what) + ": standard input (-) can only be the program or file converted");
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    throw InputError({path, 0, 0}, (errno == ENOENT ? std::string("no such file") : std::strerror(errno)) + suffix);
  }
  if (S_ISDIR(st.st_mode)) throw InputError({path, 0, 0}, "is a directory, not a file" + suffix);
  if (::access(path.c_str(), R_OK) != 0) throw InputError({path, 0, 0}, std::string("cannot read: ") + std::strerror(errno) + suffix);
}

Input open_input(const std::string& argument, std::string_view what) {
  if (argument == "-") return Input{"<stdin>", {}, read_standard_input()};
  require_input_file(argument, what);
  return Input{argument, argument, std::nullopt};
}

std::string input_head(const Input& input, std::size_t bytes) {
  if (input.text) return input.text->substr(0, bytes);
  std::ifstream in(input.path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

}  // namespace ncbridge::cli
