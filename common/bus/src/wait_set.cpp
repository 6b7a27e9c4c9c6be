#include "ncbridge/bus/wait_set.hpp"

#include "dds_check.hpp"

namespace ncbridge::bus {

WaitSet::WaitSet(Participant& participant)
    : waitset_(detail::check(dds_create_waitset(participant.handle()), "dds_create_waitset")) {}

WaitSet::~WaitSet() {
  if (waitset_ > 0) dds_delete(waitset_);
}

void WaitSet::attach(const Reader& reader) {
  detail::check(dds_waitset_attach(waitset_, reader.read_condition(), 0), "dds_waitset_attach");
}

bool WaitSet::wait(std::chrono::milliseconds timeout) {
  const dds_return_t rc = dds_waitset_wait(waitset_, nullptr, 0, DDS_MSECS(timeout.count()));
  detail::check(rc, "dds_waitset_wait");
  return rc > 0;
}

}  // namespace ncbridge::bus
