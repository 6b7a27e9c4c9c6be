#pragma once
// A job of the ncbridge/programs topic (proto/program.proto) as a C++ value, and its codec.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::wire {

// Same enumerators, same order as ncbridge::interpreter::Dialect (the service main maps them).
enum class Dialect : std::uint8_t { Rs274Ngc, Fanuc, Mach3, Siemens840D, Heidenhain, Auto };
enum class ConformanceClass : std::uint8_t { Cc1, Cc2 };

struct Job {
  std::string job_id;
  std::string file_name;
  std::string program_text;
  Dialect dialect = Dialect::Rs274Ngc;
  std::vector<setup::Tool> tools;
  std::optional<setup::Stock> stock;
  std::vector<std::string> subroutine_path;
  ConformanceClass level = ConformanceClass::Cc1;
  std::string output_name;   // FILE_NAME.name of the Part 21 file; empty: the step_writer derives one
};

std::string encode_job(const Job& job);
Job decode_job(std::string_view bytes);  // throws InputError on malformed bytes

}  // namespace ncbridge::wire
