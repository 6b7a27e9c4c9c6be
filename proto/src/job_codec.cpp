#include "ncbridge/wire/job.hpp"

#include <utility>

#include "parse_or_throw.hpp"
#include "program.pb.h"

namespace ncbridge::wire {

std::string encode_job(const Job& job) {
  pb::Job m;
  m.set_job_id(job.job_id);
  m.set_file_name(job.file_name);
  m.set_program_text(job.program_text);
  m.set_dialect(static_cast<pb::Dialect>(job.dialect));
  for (const setup::Tool& t : job.tools) {
    auto* o = m.add_tools();
    o->set_number(t.number);
    o->set_name(t.name);
    o->set_type(static_cast<pb::ToolType>(t.type));
    o->set_diameter(t.diameter);
    o->set_length(t.length);
    o->set_corner_radius(t.corner_radius);
    o->set_flute_length(t.flute_length);
    o->set_flutes(t.flutes);
    o->set_point_angle(t.point_angle);
    o->set_thread_pitch(t.thread_pitch);
    o->set_x_offset(t.x_offset);
    o->set_pocket(t.pocket);
  }
  if (job.stock) {
    auto* s = m.mutable_stock();
    s->set_min_x(job.stock->min[0]); s->set_min_y(job.stock->min[1]); s->set_min_z(job.stock->min[2]);
    s->set_max_x(job.stock->max[0]); s->set_max_y(job.stock->max[1]); s->set_max_z(job.stock->max[2]);
  }
  for (const std::string& p : job.subroutine_path) m.mutable_setup()->add_subroutine_path(p);
  m.set_level(static_cast<pb::ConformanceClass>(job.level));
  m.set_output_name(job.output_name);
  return m.SerializeAsString();
}

Job decode_job(std::string_view bytes) {
  using namespace detail;
  const char* what = "job";
  pb::Job m;
  parse_or_throw(m, bytes, what);
  Job job;
  job.job_id = m.job_id();
  job.file_name = m.file_name();
  job.program_text = std::move(*m.mutable_program_text());
  job.dialect = enum_in_range<Dialect>(m.dialect(), 6, what, "dialect");
  for (const auto& o : m.tools()) {
    setup::Tool t;
    t.number = o.number();
    t.name = o.name();
    t.type = enum_in_range<setup::ToolType>(o.type(), 13, what, "tool type");
    t.diameter = o.diameter();
    t.length = o.length();
    t.corner_radius = o.corner_radius();
    t.flute_length = o.flute_length();
    t.flutes = o.flutes();
    t.point_angle = o.point_angle();
    t.thread_pitch = o.thread_pitch();
    t.x_offset = o.x_offset();
    t.pocket = o.pocket();
    job.tools.push_back(std::move(t));
  }
  if (m.has_stock()) {
    const auto& s = m.stock();
    job.stock = setup::Stock{{s.min_x(), s.min_y(), s.min_z()}, {s.max_x(), s.max_y(), s.max_z()}};
  }
  for (const auto& p : m.setup().subroutine_path()) job.subroutine_path.push_back(p);
  job.level = enum_in_range<ConformanceClass>(m.level(), 2, what, "level");
  job.output_name = m.output_name();
  return job;
}

}  // namespace ncbridge::wire
