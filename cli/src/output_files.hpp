#pragma once
// Every file an `ncbridge` command writes goes through one OutputSet per run:
//
//   OutputSet outputs;                                    // before any work starts:
//   OutputFile& stp = outputs.add(args.output, "-o");     //   checks the path now
//   OutputFile* report = args.report.empty() ? nullptr : &outputs.add(args.report, "--report");
//   outputs.protect(args.program);                        //   no output may replace an input
//   ... stp.write(text); report->write(text); ...         // any number of pieces, any size
//   outputs.commit();                                     // all appear together
//
// What an output path means:
//   "-", /dev/stdout, /dev/fd/N    standard output (file descriptor N); one output each at most
//   a regular file, or nothing yet the file is replaced atomically (its permissions are kept, and
//                                  its owner when root writes it; hard links to it are not)
//   a symbolic link                followed: the file it leads to is replaced, the link stays
//   /dev/null                      written nowhere
//   another character device, FIFO written through (opened and written, never replaced)
//   a directory, block device, socket, missing directory   refused (OutputError)
// add() throws OutputError (exit 3) for a path that cannot be written and UsageError (exit 2)
// for two outputs to the same place or an output that is an input of the run.
//
// All or nothing: until commit() nothing is visible. Files are written to temporaries without a
// name (O_TMPFILE) in their target's directory; standard output and devices to a spool.
// commit() syncs every temporary, then writes the streams, then gives each file its name
// (renames over the old one); if a rename fails, the files already renamed get their old
// contents back. An OutputSet destroyed without commit() (an error on the way) leaves every old
// file as it was and no temporary behind; so does a killed process.
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::cli {

class OutputFile {
 public:
  enum class Kind { File, Descriptor, Device, Discard };

  OutputFile(std::string argument, std::string option, Kind kind, std::filesystem::path target, int descriptor);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(std::string_view bytes);
  std::uint64_t bytes_written() const { return written_; }
  // The path as given ("-" included), and what messages call it ("standard output" for "-").
  const std::string& argument() const { return argument_; }
  std::string display_name() const;
  // The name a file format may record (Part 21 FILE_NAME): the file name, "" for a stream.
  std::string file_name() const;
  bool is_stream() const { return kind_ == Kind::Descriptor || kind_ == Kind::Device; }
  Kind kind() const { return kind_; }
  const std::filesystem::path& target() const { return target_; }  // the file replaced or written

 private:
  friend class OutputSet;
  void flush();
  void write_all(std::string_view bytes);
  void open_temporary();
  void sync();                   // commit phase 1
  void send_to_stream();         // commit phase 2 (streams)
  void rename_into_place(bool keep_backup);  // commit phase 3 (files)
  void restore_backup() noexcept;
  void drop_backup() noexcept;
  [[noreturn]] void fail(const std::string& what) const;

  std::string argument_, option_;
  Kind kind_;
  std::filesystem::path target_;
  int descriptor_ = -1;  // Kind::Descriptor: the file descriptor written at commit
  int fd_ = -1;          // the temporary or spool
  bool named_temporary_ = false;      // a mkstemp file (no O_TMPFILE here), removed if not committed
  std::filesystem::path temporary_;   // its name, or the name linked for the rename
  std::filesystem::path backup_;      // the old file while the set's renames are in progress
  bool replaced_ = false, existed_ = false;
  std::string buffer_;
  std::uint64_t written_ = 0;
};

class OutputSet {
 public:
  OutputSet() = default;
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  OutputSet(OutputSet&&) = default;  // the OutputFile references stay valid
  OutputSet& operator=(OutputSet&&) = default;

  // Checks `path` (see above) and returns where to write it; `option` names it in messages
  // ("-o", "--report"). The reference stays valid for the set's life.
  OutputFile& add(const std::string& path, const std::string& option);
  // An input of the run: an output that is the same file is refused (it would be replaced).
  void protect(const std::filesystem::path& input);
  // Makes every output visible (see above); throws OutputError, leaving old files as they were.
  void commit();
  bool empty() const { return files_.empty(); }

 private:
  struct Identity {
    dev_t device = 0;
    ino_t inode = 0;
  };
  void refuse_same_as_input(const OutputFile& file, const Identity& input) const;

  std::vector<std::unique_ptr<OutputFile>> files_;
  std::vector<std::pair<std::string, Identity>> inputs_;
  bool committed_ = false;
};

// A folder for outputs (--output-dir): created with its parents when missing; OutputError when
// it is something else or cannot be written.
std::filesystem::path prepare_output_directory(const std::string& path, const std::string& option);

}  // namespace ncbridge::cli
