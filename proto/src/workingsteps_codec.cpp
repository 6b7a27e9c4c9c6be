#include "ncbridge/wire/workingsteps.hpp"

#include <utility>

#include "parse_or_throw.hpp"
#include "workingsteps.pb.h"

namespace ncbridge::wire {

std::string encode_stepnc_model(const StepncModel& model) {
  pb::StepncModel m;
  m.set_job_id(model.job_id);
  m.set_seq(model.seq);
  m.set_last(model.last);
  m.set_level(static_cast<pb::ModelLevel>(model.level));
  m.set_requested(static_cast<pb::ModelLevel>(model.requested));
  m.set_output_name(model.output_name);
  m.set_model(model.model);
  m.set_model_size(model.model.size());
  return m.SerializeAsString();
}

StepncModel decode_stepnc_model(std::string_view bytes) {
  using namespace detail;
  const char* what = "stepnc model";
  pb::StepncModel m;
  parse_or_throw(m, bytes, what);
  if (!m.has_model_size() || m.model_size() != m.model().size())
    malformed(what, "model size missing or wrong (truncated sample, or not a stepnc model)");
  StepncModel out;
  out.job_id = m.job_id();
  out.seq = m.seq();
  out.last = m.last();
  out.level = enum_in_range<ModelLevel>(m.level(), 2, what, "level");
  out.requested = enum_in_range<ModelLevel>(m.requested(), 2, what, "requested level");
  out.output_name = m.output_name();
  out.model = std::move(*m.mutable_model());
  return out;
}

}  // namespace ncbridge::wire
