// LD_PRELOAD shim for bench/scaleout/run.sh: counts the bytes and datagrams this process
// receives and sends on its sockets (Cyclone DDS uses recvmsg/sendmsg), in a small file
// $NCBRIDGE_NET_COUNTERS/<pid> that the benchmark reads while the process runs (4 unsigned
// 64-bit numbers: bytes received, datagrams received, bytes sent, datagrams sent).
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

struct Counters {
  std::atomic<std::uint64_t> received_bytes, received, sent_bytes, sent;
};
Counters* counters = nullptr;

using RecvMsg = ssize_t (*)(int, msghdr*, int);
using RecvFrom = ssize_t (*)(int, void*, size_t, int, sockaddr*, socklen_t*);
using SendMsg = ssize_t (*)(int, const msghdr*, int);
using SendTo = ssize_t (*)(int, const void*, size_t, int, const sockaddr*, socklen_t);

template <class F>
F next(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

__attribute__((constructor)) void open_counters() {
  const char* dir = std::getenv("NCBRIDGE_NET_COUNTERS");
  if (dir == nullptr) return;
  char path[4096];
  std::snprintf(path, sizeof path, "%s/%d", dir, static_cast<int>(getpid()));
  const int fd = open(path, O_RDWR | O_CREAT | O_TRUNC, 0644);
  if (fd < 0 || ftruncate(fd, sizeof(Counters)) != 0) return;
  void* p = mmap(nullptr, sizeof(Counters), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  if (p != MAP_FAILED) counters = static_cast<Counters*>(p);
}

void count_in(ssize_t n) {
  if (counters == nullptr || n <= 0) return;
  counters->received_bytes += static_cast<std::uint64_t>(n);
  counters->received += 1;
}

void count_out(ssize_t n) {
  if (counters == nullptr || n <= 0) return;
  counters->sent_bytes += static_cast<std::uint64_t>(n);
  counters->sent += 1;
}

}  // namespace

extern "C" {

ssize_t recvmsg(int fd, msghdr* msg, int flags) {
  static const RecvMsg real = next<RecvMsg>("recvmsg");
  const ssize_t n = real(fd, msg, flags);
  count_in(n);
  return n;
}

ssize_t recvfrom(int fd, void* buf, size_t len, int flags, sockaddr* from, socklen_t* from_len) {
  static const RecvFrom real = next<RecvFrom>("recvfrom");
  const ssize_t n = real(fd, buf, len, flags, from, from_len);
  count_in(n);
  return n;
}

ssize_t sendmsg(int fd, const msghdr* msg, int flags) {
  static const SendMsg real = next<SendMsg>("sendmsg");
  const ssize_t n = real(fd, msg, flags);
  count_out(n);
  return n;
}

ssize_t sendto(int fd, const void* buf, size_t len, int flags, const sockaddr* to, socklen_t to_len) {
  static const SendTo real = next<SendTo>("sendto");
  const ssize_t n = real(fd, buf, len, flags, to, to_len);
  count_out(n);
  return n;
}

}  // extern "C"
