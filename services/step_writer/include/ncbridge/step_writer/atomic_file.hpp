#pragma once
// Writes a whole file or nothing: a temporary file in the same directory, fsync, rename over the
// target, fsync of the directory. A failure leaves the target as it was and removes the temporary.
#include <filesystem>
#include <string_view>

namespace ncbridge::step_writer {

// Throws std::system_error (with the path in the message) when any step fails.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace ncbridge::step_writer
