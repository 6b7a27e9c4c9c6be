#include "ncbridge/bus/wait_set.hpp"

#include "dds_check.hpp"

namespace ncbridge::bus {

WaitSet::WaitSet(Participant& participant)
    : waitset_(detail::check(dds_create_waitset(participant.handle()), "dds_create_waitset")) {
  try {
    guard_ = detail::check(dds_create_guardcondition(participant.handle()), "dds_create_guardcondition");
    detail::check(dds_waitset_attach(waitset_, guard_, 0), "dds_waitset_attach");
  } catch (...) {
    if (guard_ > 0) dds_delete(guard_);
    dds_delete(waitset_);
    throw;
  }
}

WaitSet::~WaitSet() {
  if (waitset_ > 0) dds_delete(waitset_);  // detaches the guard condition
  if (guard_ > 0) dds_delete(guard_);
}

void WaitSet::wake() { detail::check(dds_set_guardcondition(guard_, true), "dds_set_guardcondition"); }

void WaitSet::attach(const Reader& reader) {
  detail::check(dds_waitset_attach(waitset_, reader.read_condition(), 0), "dds_waitset_attach");
}

bool WaitSet::wait(std::chrono::milliseconds timeout) {
  const dds_return_t rc = dds_waitset_wait(waitset_, nullptr, 0, DDS_MSECS(timeout.count()));
  detail::check(rc, "dds_waitset_wait");
  bool woken = false;
  dds_take_guardcondition(guard_, &woken);
  return rc > 0;
}

}  // namespace ncbridge::bus
