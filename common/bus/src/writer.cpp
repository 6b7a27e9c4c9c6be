#include "ncbridge/bus/writer.hpp"

#include <thread>
#include <utility>

#include "topic_entity.hpp"

namespace ncbridge::bus {

Writer::Writer(Participant& participant, Topic topic, std::string_view partition) : topic_(topic) {
  topic_entity_ = detail::create_topic(participant.handle(), topic);
  dds_entity_t parent = participant.handle();
  if (!partition.empty()) {
    try {
      publisher_ = detail::create_publisher(participant.handle(), partition);
    } catch (...) {
      reset();
      throw;
    }
    parent = publisher_;
  }
  const detail::QosPtr qos = detail::make_qos(qos_profile(topic), detail::Endpoint::Writer);
  writer_ = dds_create_writer(parent, topic_entity_, qos.get(), nullptr);
  if (writer_ < 0) {
    const std::int32_t rc = writer_;
    writer_ = 0;
    reset();
    detail::check(rc, "dds_create_writer");
  }
}

Writer::~Writer() { reset(); }

Writer::Writer(Writer&& other) noexcept
    : publisher_(std::exchange(other.publisher_, 0)),
      topic_entity_(std::exchange(other.topic_entity_, 0)),
      writer_(std::exchange(other.writer_, 0)),
      topic_(other.topic_) {}

Writer& Writer::operator=(Writer&& other) noexcept {
  if (this != &other) {
    reset();
    publisher_ = std::exchange(other.publisher_, 0);
    topic_entity_ = std::exchange(other.topic_entity_, 0);
    writer_ = std::exchange(other.writer_, 0);
    topic_ = other.topic_;
  }
  return *this;
}

void Writer::reset() noexcept {
  if (writer_ > 0) dds_delete(writer_);
  if (publisher_ > 0) dds_delete(publisher_);
  if (topic_entity_ > 0) dds_delete(topic_entity_);
  writer_ = 0;
  publisher_ = 0;
  topic_entity_ = 0;
}

void Writer::write(const Envelope& e) { write(e.key, e.subkey, e.seq, e.kind, e.last, e.payload); }

void Writer::write(std::string_view key, std::string_view subkey, std::uint64_t seq, std::uint32_t kind, bool last,
                   std::string_view payload) {
  if (payload.size() > 0xffffffffu) throw BusError("payload larger than 4 GiB");
  const std::string k(key), s(subkey);  // IDL strings are NUL-terminated
  ncbridge_bus_Envelope sample = detail::key_sample(k, s);
  sample.seq = seq;
  sample.kind = kind;
  sample.last = last;
  sample.payload._length = sample.payload._maximum = static_cast<std::uint32_t>(payload.size());
  sample.payload._buffer = reinterpret_cast<std::uint8_t*>(const_cast<char*>(payload.data()));
  sample.payload._release = false;
  detail::check(dds_write(writer_, &sample), "dds_write");
}

void Writer::unregister(std::string_view key, std::string_view subkey) {
  const std::string k(key), s(subkey);
  const ncbridge_bus_Envelope sample = detail::key_sample(k, s);
  detail::check(dds_unregister_instance(writer_, &sample), "dds_unregister_instance");
}

void Writer::dispose(std::string_view key, std::string_view subkey) {
  const std::string k(key), s(subkey);
  const ncbridge_bus_Envelope sample = detail::key_sample(k, s);
  detail::check(dds_dispose(writer_, &sample), "dds_dispose");
}

bool Writer::wait_for_acks(std::chrono::milliseconds timeout) {
  const dds_return_t rc = dds_wait_for_acks(writer_, DDS_MSECS(timeout.count()));
  if (rc == DDS_RETCODE_TIMEOUT) return false;
  detail::check(rc, "dds_wait_for_acks");
  return true;
}

std::uint32_t Writer::matched_readers() const {
  dds_publication_matched_status_t status{};
  detail::check(dds_get_publication_matched_status(writer_, &status), "dds_get_publication_matched_status");
  return status.current_count;
}

bool Writer::wait_for_readers(std::uint32_t count, std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (matched_readers() < count) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

}  // namespace ncbridge::bus
