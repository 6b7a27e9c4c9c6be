#pragma once
// SIGTERM / SIGINT as a flag the service loop polls, with no signal handler and no global:
// the signals are blocked in the process and read from a signalfd.
namespace ncbridge::service {

class ShutdownSignal {
 public:
  ShutdownSignal();  // blocks SIGTERM and SIGINT (call before starting threads); throws on failure
  ~ShutdownSignal();
  ShutdownSignal(const ShutdownSignal&) = delete;
  ShutdownSignal& operator=(const ShutdownSignal&) = delete;

  // True once SIGTERM or SIGINT arrived (stays true).
  bool requested();

 private:
  int fd_ = -1;
  bool requested_ = false;
};

}  // namespace ncbridge::service
