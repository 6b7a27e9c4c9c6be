#include "ncbridge/bus/reader.hpp"

#include <array>
#include <thread>
#include <utility>

#include "topic_entity.hpp"

namespace ncbridge::bus {
namespace {

InstanceState state_of(dds_instance_state_t s) {
  switch (s) {
    case DDS_IST_NOT_ALIVE_DISPOSED: return InstanceState::Disposed;
    case DDS_IST_NOT_ALIVE_NO_WRITERS: return InstanceState::NoWriters;
    default: return InstanceState::Alive;
  }
}

}  // namespace

Reader::Reader(Participant& participant, Topic topic, std::string_view partition) : topic_(topic) {
  try {
    topic_entity_ = detail::create_topic(participant.handle(), topic);
    dds_entity_t parent = participant.handle();
    if (!partition.empty()) parent = subscriber_ = detail::create_subscriber(participant.handle(), partition);
    const detail::QosPtr qos = detail::make_qos(qos_profile(topic), detail::Endpoint::Reader);
    reader_ = detail::check(dds_create_reader(parent, topic_entity_, qos.get(), nullptr),
                            "dds_create_reader");
    condition_ = detail::check(dds_create_readcondition(reader_, DDS_ANY_STATE), "dds_create_readcondition");
    waitset_ = detail::check(dds_create_waitset(participant.handle()), "dds_create_waitset");
    detail::check(dds_waitset_attach(waitset_, condition_, 0), "dds_waitset_attach");
  } catch (...) {
    reset();
    throw;
  }
}

Reader::~Reader() { reset(); }

Reader::Reader(Reader&& other) noexcept
    : subscriber_(std::exchange(other.subscriber_, 0)),
      topic_entity_(std::exchange(other.topic_entity_, 0)),
      reader_(std::exchange(other.reader_, 0)),
      waitset_(std::exchange(other.waitset_, 0)),
      condition_(std::exchange(other.condition_, 0)),
      topic_(other.topic_) {}

Reader& Reader::operator=(Reader&& other) noexcept {
  if (this != &other) {
    reset();
    subscriber_ = std::exchange(other.subscriber_, 0);
    topic_entity_ = std::exchange(other.topic_entity_, 0);
    reader_ = std::exchange(other.reader_, 0);
    waitset_ = std::exchange(other.waitset_, 0);
    condition_ = std::exchange(other.condition_, 0);
    topic_ = other.topic_;
  }
  return *this;
}

void Reader::reset() noexcept {
  if (waitset_ > 0) dds_delete(waitset_);      // detaches the condition
  if (reader_ > 0) dds_delete(reader_);        // deletes its read condition too
  if (subscriber_ > 0) dds_delete(subscriber_);
  if (topic_entity_ > 0) dds_delete(topic_entity_);
  waitset_ = reader_ = condition_ = subscriber_ = topic_entity_ = 0;
}

std::size_t Reader::take_now(std::vector<Received>& out, std::size_t max) {
  constexpr std::size_t kChunk = 64;
  std::size_t taken = 0;
  while (taken < max) {
    std::array<void*, kChunk> samples{};  // all null: Cyclone lends its buffers
    std::array<dds_sample_info_t, kChunk> infos{};
    const std::size_t want = std::min(kChunk, max - taken);
    const dds_return_t n = dds_take(reader_, samples.data(), infos.data(), want, static_cast<std::uint32_t>(want));
    detail::check(n, "dds_take");
    for (dds_return_t i = 0; i < n; ++i) {
      const auto* s = static_cast<const ncbridge_bus_Envelope*>(samples[static_cast<std::size_t>(i)]);
      const dds_sample_info_t& info = infos[static_cast<std::size_t>(i)];
      Received r;
      r.has_data = info.valid_data;
      r.state = state_of(info.instance_state);
      // State-only samples (dispose, no writers) carry the key fields only.
      r.envelope.key = s->id ? s->id : "";
      r.envelope.subkey = s->sub_id ? s->sub_id : "";
      if (info.valid_data) {
        r.envelope.seq = s->seq;
        r.envelope.kind = s->kind;
        r.envelope.last = s->last;
        if (s->payload._length > 0)
          r.envelope.payload.assign(reinterpret_cast<const char*>(s->payload._buffer), s->payload._length);
      }
      out.push_back(std::move(r));
    }
    if (n > 0) dds_return_loan(reader_, samples.data(), n);
    taken += static_cast<std::size_t>(n);
    if (static_cast<std::size_t>(n) < want) break;
  }
  return taken;
}

std::vector<Received> Reader::take(std::chrono::milliseconds timeout, std::size_t max) {
  std::vector<Received> out;
  if (take_now(out, max) > 0) return out;
  const dds_return_t rc = dds_waitset_wait(waitset_, nullptr, 0, DDS_MSECS(timeout.count()));
  detail::check(rc, "dds_waitset_wait");
  if (rc > 0) take_now(out, max);
  return out;
}

bool Reader::wait_for_writers(std::uint32_t count, std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    dds_subscription_matched_status_t status{};
    detail::check(dds_get_subscription_matched_status(reader_, &status), "dds_get_subscription_matched_status");
    if (status.current_count >= count) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace ncbridge::bus
