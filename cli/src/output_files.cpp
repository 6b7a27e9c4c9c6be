#include "output_files.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>

#include "errors.hpp"

namespace ncbridge::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kBufferBytes = std::size_t{1} << 16;
constexpr int kMaxSymlinkHops = 40;

std::string error_text(int error) { return std::strerror(error); }

[[noreturn]] void refuse(const std::string& path, const std::string& option, const std::string& why) {
  throw OutputError(path, why + " (" + option + ")");
}

// /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N, /proc/PID/fd/N of this process: a file
// descriptor of ours, written as such (not the file it happens to lead to).
std::optional<int> descriptor_alias(const fs::path& path) {
  const std::string p = path.lexically_normal().string();
  if (p == "/dev/stdout") return 1;
  if (p == "/dev/stderr") return 2;
  const std::string own_proc = "/proc/" + std::to_string(::getpid()) + "/fd/";
  for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"), own_proc}) {
    if (p.size() > prefix.size() && p.compare(0, prefix.size(), prefix) == 0) {
      int fd = -1;
      const char* first = p.data() + prefix.size();
      const char* last = p.data() + p.size();
      const auto [end, ec] = std::from_chars(first, last, fd);
      if (ec == std::errc() && end == last && fd >= 0) return fd;
    }
  }
  return std::nullopt;
}

fs::path directory_of(const fs::path& file) {
  const fs::path dir = file.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

void check_directory_for(const fs::path& file, const std::string& argument, const std::string& option) {
  const fs::path dir = directory_of(file);
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) {
    if (errno == ENOENT) refuse(argument, option, "the directory " + dir.string() + " does not exist");
    refuse(argument, option, "cannot use the directory " + dir.string() + ": " + error_text(errno));
  }
  if (!S_ISDIR(st.st_mode)) refuse(argument, option, dir.string() + " is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    refuse(argument, option, "cannot write in the directory " + dir.string() + ": " + error_text(errno));
  }
}

struct Resolved {
  OutputFile::Kind kind = OutputFile::Kind::File;
  fs::path target;
  int descriptor = -1;
};

Resolved resolve(const std::string& argument, const std::string& option) {
  if (argument.empty()) throw UsageError(option + ": an empty output path");
  if (argument == "-") return {OutputFile::Kind::Descriptor, {}, 1};
  fs::path p = argument;
  for (int hops = 0;; ++hops) {
    if (const auto fd = descriptor_alias(p)) return {OutputFile::Kind::Descriptor, p, *fd};
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0) {
      if (errno == ENOTDIR) refuse(argument, option, directory_of(p).string() + " is not a directory");
      if (errno != ENOENT) refuse(argument, option, "cannot use this path: " + error_text(errno));
      check_directory_for(p, argument, option);  // a new file (or a link's missing target)
      return {OutputFile::Kind::File, p, -1};
    }
    if (S_ISLNK(st.st_mode)) {
      if (hops == kMaxSymlinkHops) refuse(argument, option, "too many levels of symbolic links");
      std::error_code ec;
      const fs::path link = fs::read_symlink(p, ec);
      if (ec) refuse(argument, option, "cannot read the symbolic link " + p.string() + ": " + ec.message());
      p = link.is_absolute() ? link : p.parent_path() / link;
      continue;
    }
    if (S_ISREG(st.st_mode)) {
      check_directory_for(p, argument, option);
      if (::access(p.c_str(), W_OK) != 0) refuse(argument, option, "the file is not writable: " + error_text(errno));
      return {OutputFile::Kind::File, p, -1};
    }
    if (S_ISDIR(st.st_mode)) refuse(argument, option, "is a directory");
    if (S_ISCHR(st.st_mode) && st.st_rdev == makedev(1, 3)) return {OutputFile::Kind::Discard, p, -1};
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      if (::access(p.c_str(), W_OK) != 0) refuse(argument, option, "cannot write to this device: " + error_text(errno));
      return {OutputFile::Kind::Device, p, -1};
    }
    if (S_ISBLK(st.st_mode)) refuse(argument, option, "is a block device (a disk): ncbridge does not write to it");
    if (S_ISSOCK(st.st_mode)) refuse(argument, option, "is a socket: ncbridge writes files, not to sockets");
    refuse(argument, option, "is not a file ncbridge can write");
  }
}

void check_descriptor(int fd, const std::string& argument, const std::string& option) {
  const int flags = ::fcntl(fd, F_GETFL);
  const std::string name = fd == 1 ? "standard output" : "file descriptor " + std::to_string(fd);
  if (flags < 0) refuse(argument, option, name + " is not open");
  if ((flags & O_ACCMODE) == O_RDONLY) refuse(argument, option, name + " is not open for writing");
}

// An anonymous temporary in `dir` (O_TMPFILE), or -1 when the file system cannot make one.
int unnamed_temporary(const fs::path& dir, int flags, mode_t mode) {
  const int fd = ::open(dir.c_str(), O_TMPFILE | flags | O_CLOEXEC, mode);
  if (fd < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) errno = EOPNOTSUPP;
  return fd;
}

std::string random_suffix() {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(random()));
  return text;
}

// ".NAME.ncbridge-": the start of the names ncbridge gives its files beside NAME.
std::string temporary_stem(const fs::path& target) {
  std::string stem(1, '.');
  stem.append(target.filename().string()).append(".ncbridge-");
  return stem;
}

void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // the renames are done; a directory we cannot open cannot be synced
  ::fsync(fd);
  ::close(fd);
}

// SIGPIPE ignored while streams are written: a reader that went away is an error to report
// (and temporaries to clean up), not a silent death.
class IgnoreSigpipe {
 public:
  IgnoreSigpipe() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, &saved_);
  }
  ~IgnoreSigpipe() { ::sigaction(SIGPIPE, &saved_, nullptr); }
  IgnoreSigpipe(const IgnoreSigpipe&) = delete;
  IgnoreSigpipe& operator=(const IgnoreSigpipe&) = delete;

 private:
  struct sigaction saved_ {};
};

}  // namespace

// ---- OutputFile ----

OutputFile::OutputFile(std::string argument, std::string option, Kind kind, fs::path target, int descriptor)
    : argument_(std::move(argument)), option_(std::move(option)), kind_(kind), target_(std::move(target)),
      descriptor_(descriptor) {}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

std::string OutputFile::display_name() const {
  if (kind_ == Kind::Descriptor && argument_ == "-") return "standard output";
  return argument_;
}

std::string OutputFile::file_name() const {
  if (kind_ != Kind::File) return "";
  return fs::path(argument_).filename().string();
}

void OutputFile::fail(const std::string& what) const { throw OutputError(display_name(), what); }

void OutputFile::write(std::string_view bytes) {
  written_ += bytes.size();
  if (kind_ == Kind::Discard) return;
  if (buffer_.size() + bytes.size() < kBufferBytes) {
    buffer_.append(bytes);
    return;
  }
  flush();
  if (bytes.size() < kBufferBytes) {
    buffer_.append(bytes);
  } else {
    write_all(bytes);
  }
}

void OutputFile::open_temporary() {
  if (kind_ == Kind::File) {
    const fs::path dir = directory_of(target_);
    // linkat() gives an O_TMPFILE file its name through /proc/self/fd.
    if (::access("/proc/self/fd", X_OK) == 0) {
      fd_ = unnamed_temporary(dir, O_WRONLY, 0666);
      if (fd_ >= 0) return;
      if (errno != EOPNOTSUPP) fail("cannot create a file in " + dir.string() + ": " + error_text(errno));
    }
    std::string pattern = (dir / (temporary_stem(target_) + "XXXXXX")).string();
    fd_ = ::mkstemp(pattern.data());
    if (fd_ < 0) fail("cannot create a file in " + dir.string() + ": " + error_text(errno));
    temporary_ = pattern;
    named_temporary_ = true;
    return;
  }
  const fs::path dir = fs::temp_directory_path();
  fd_ = unnamed_temporary(dir, O_RDWR, 0600);
  if (fd_ >= 0) return;
  std::string pattern = (dir / "ncbridge-spool-XXXXXX").string();
  fd_ = ::mkstemp(pattern.data());
  if (fd_ < 0) fail("cannot create a spool file in " + dir.string() + ": " + error_text(errno));
  ::unlink(pattern.c_str());
}

void OutputFile::flush() {
  write_all(buffer_);
  buffer_.clear();
}

void OutputFile::write_all(std::string_view bytes) {
  if (bytes.empty()) return;
  if (fd_ < 0) open_temporary();
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("cannot write: " + error_text(errno));
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void OutputFile::sync() {
  if (kind_ == Kind::Discard) return;
  flush();
  if (fd_ < 0) open_temporary();  // an empty output is an empty file
  if (kind_ != Kind::File) return;
  mode_t mode = 0;
  struct stat old {};
  if (::stat(target_.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
    mode = old.st_mode & 07777;  // a replaced file keeps its permissions
    if (::geteuid() == 0) {      // and, written by root, its owner (others cannot give files away)
      if (::fchown(fd_, old.st_uid, old.st_gid) != 0) fail("cannot keep the owner: " + error_text(errno));
    }
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  if (::fchmod(fd_, mode) != 0) fail("cannot set the permissions: " + error_text(errno));
  if (::fsync(fd_) != 0) fail("cannot write: " + error_text(errno));
}

void OutputFile::send_to_stream() {
  int out = descriptor_;
  if (kind_ == Kind::Descriptor) {
    std::fflush(descriptor_ == 2 ? stderr : stdout);
  } else {
    out = ::open(target_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (out < 0) fail("cannot open: " + error_text(errno));
  }
  std::string chunk(kBufferBytes * 4, '\0');
  bool ok = ::lseek(fd_, 0, SEEK_SET) == 0;
  int error = errno;
  while (ok) {
    const ssize_t got = ::read(fd_, chunk.data(), chunk.size());
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      ok = got == 0;
      error = errno;
      break;
    }
    std::string_view rest(chunk.data(), static_cast<std::size_t>(got));
    while (ok && !rest.empty()) {
      const ssize_t n = ::write(out, rest.data(), rest.size());
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        ok = false;
        error = errno;
      } else {
        rest.remove_prefix(static_cast<std::size_t>(n));
      }
    }
  }
  if (kind_ == Kind::Device && ::close(out) != 0 && ok) {
    ok = false;
    error = errno;
  }
  if (!ok) fail("cannot write: " + error_text(error));
}

void OutputFile::rename_into_place(bool keep_backup) {
  const fs::path dir = directory_of(target_);
  const std::string stem = temporary_stem(target_);
  if (!named_temporary_) {  // give the O_TMPFILE file a name beside its target
    const std::string self = "/proc/self/fd/" + std::to_string(fd_);
    for (int attempt = 0; temporary_.empty(); ++attempt) {
      const fs::path name = dir / (stem + random_suffix());
      if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) {
        temporary_ = name;
      } else if (errno != EEXIST || attempt == 10) {
        fail("cannot create a file in " + dir.string() + ": " + error_text(errno));
      }
    }
  }
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("cannot write: " + error_text(errno));
  struct stat old {};
  existed_ = ::lstat(target_.c_str(), &old) == 0;
  if (keep_backup && existed_ && S_ISREG(old.st_mode)) {
    const fs::path name = dir / (stem + "old-" + random_suffix());
    if (::link(target_.c_str(), name.c_str()) == 0) backup_ = name;  // else: no way back for this one
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail("cannot replace the file: " + error_text(errno));
  temporary_.clear();
  replaced_ = true;
}

void OutputFile::restore_backup() noexcept {
  if (!replaced_) {
    drop_backup();
    return;
  }
  replaced_ = false;
  if (!backup_.empty()) {
    // A backup that cannot be renamed back stays: it is the only copy of the old file.
    if (::rename(backup_.c_str(), target_.c_str()) == 0) backup_.clear();
  } else if (!existed_) {
    ::unlink(target_.c_str());
  }
}

void OutputFile::drop_backup() noexcept {
  if (!backup_.empty()) ::unlink(backup_.c_str());
  backup_.clear();
}

// ---- OutputSet ----

OutputSet::~OutputSet() = default;

OutputFile& OutputSet::add(const std::string& path, const std::string& option) {
  if (committed_) throw std::logic_error("OutputSet::add after commit");
  Resolved r = resolve(path, option);
  if (r.kind == OutputFile::Kind::Descriptor) check_descriptor(r.descriptor, path, option);
  auto file = std::make_unique<OutputFile>(path, option, r.kind, r.target, r.descriptor);
  for (const auto& other : files_) {
    const auto& a = *other;
    const auto& b = *file;
    bool same = false;
    if (a.kind_ == OutputFile::Kind::Descriptor && b.kind_ == OutputFile::Kind::Descriptor) {
      same = a.descriptor_ == b.descriptor_;
    } else if (a.kind_ == b.kind_ && a.kind_ != OutputFile::Kind::Discard) {
      std::error_code ea, eb;
      const fs::path ta = fs::weakly_canonical(fs::absolute(a.target_), ea);
      const fs::path tb = fs::weakly_canonical(fs::absolute(b.target_), eb);
      same = !ea && !eb && ta == tb;
    }
    if (same) {
      throw UsageError(a.option_ + " and " + b.option_ + " name the same output (" + b.display_name() + ")");
    }
  }
  for (const auto& [input, identity] : inputs_) refuse_same_as_input(*file, identity);
  files_.push_back(std::move(file));
  return *files_.back();
}

void OutputSet::refuse_same_as_input(const OutputFile& file, const Identity& input) const {
  if (file.kind_ != OutputFile::Kind::File) return;
  struct stat st {};
  if (::stat(file.target_.c_str(), &st) != 0) return;
  if (st.st_dev == input.device && st.st_ino == input.inode) {
    throw UsageError(file.option_ + " " + file.argument_ + " is an input of this run; it would be replaced");
  }
}

void OutputSet::protect(const fs::path& input) {
  if (input.empty() || input == "-") return;
  struct stat st {};
  if (::stat(input.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  const Identity identity{st.st_dev, st.st_ino};
  for (const auto& file : files_) refuse_same_as_input(*file, identity);
  inputs_.emplace_back(input.string(), identity);
}

void OutputSet::commit() {
  if (committed_) throw std::logic_error("OutputSet::commit called twice");
  for (const auto& f : files_) f->sync();
  {
    const IgnoreSigpipe guard;
    for (const auto& f : files_) {
      if (f->is_stream()) f->send_to_stream();
    }
  }
  const auto files = std::count_if(files_.begin(), files_.end(),
                                   [](const auto& f) { return f->kind_ == OutputFile::Kind::File; });
  try {
    for (const auto& f : files_) {
      if (f->kind_ == OutputFile::Kind::File) f->rename_into_place(files > 1);
    }
  } catch (...) {
    for (auto it = files_.rbegin(); it != files_.rend(); ++it) (*it)->restore_backup();
    throw;
  }
  std::set<fs::path> directories;
  for (const auto& f : files_) {
    f->drop_backup();
    if (f->kind_ == OutputFile::Kind::File) directories.insert(directory_of(f->target_));
  }
  for (const fs::path& dir : directories) sync_directory(dir);
  committed_ = true;
}

fs::path prepare_output_directory(const std::string& path, const std::string& option) {
  if (path.empty()) throw UsageError(option + ": an empty directory path");
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) refuse(path, option, "is not a directory");
  } else if (!fs::create_directories(path, ec) && ec) {
    refuse(path, option, "cannot create the directory: " + ec.message());
  }
  if (::access(path.c_str(), W_OK | X_OK) != 0) refuse(path, option, "cannot write in this directory: " + error_text(errno));
  return path;
}

}  // namespace ncbridge::cli
