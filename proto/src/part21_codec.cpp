#include "ncbridge/wire/part21.hpp"

#include <algorithm>
#include <utility>

#include "parse_or_throw.hpp"
#include "part21.pb.h"

namespace ncbridge::wire {

std::string encode_part21(const Part21File& file) {
  pb::Part21File m;
  m.set_job_id(file.job_id);
  m.set_level(static_cast<pb::Part21Level>(file.level));
  m.set_file_name(file.file_name);
  m.set_content(file.content);
  m.set_sha256(std::string(file.sha256.begin(), file.sha256.end()));
  m.set_seq(file.seq);
  m.set_more(file.more);
  return m.SerializeAsString();
}

Part21File decode_part21(std::string_view bytes) {
  using namespace detail;
  const char* what = "part21 file";
  pb::Part21File m;
  parse_or_throw(m, bytes, what);
  Part21File f;
  f.job_id = m.job_id();
  f.level = enum_in_range<Part21Level>(m.level(), 2, what, "level");
  f.file_name = m.file_name();
  f.content = std::move(*m.mutable_content());
  if (m.sha256().size() != f.sha256.size())
    malformed(what, "sha256 digest has " + std::to_string(m.sha256().size()) + " bytes, not 32");
  std::copy(m.sha256().begin(), m.sha256().end(), f.sha256.begin());
  f.seq = m.seq();
  f.more = m.more();
  return f;
}

}  // namespace ncbridge::wire
