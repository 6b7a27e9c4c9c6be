#pragma once
// Writes a whole file or nothing: a temporary file in the same directory, fsync, rename over the
// target, fsync of the directory. A failure leaves the target as it was and removes the temporary.
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace ncbridge::step_writer {

// Throws std::system_error (with the path in the message) when any step fails.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// The same, for contents made piece by piece: write() as often as needed, then commit(). Until
// commit() the target is untouched; destroying an AtomicFile that was not committed (an error on
// the way) removes the temporary file. Throws std::system_error like write_file_atomically.
class AtomicFile {
 public:
  explicit AtomicFile(const std::filesystem::path& target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view bytes);
  void commit();
  std::uint64_t bytes_written() const { return written_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  bool committed_ = false;
  std::uint64_t written_ = 0;
};

}  // namespace ncbridge::step_writer
