#pragma once
// What a command says besides its results, warnings and errors, by verbosity (-q, -v): a
// one-line summary when it succeeded, details with -v, and a progress line on a terminal for a
// run of more than about a second. Warnings and errors are printed whatever the verbosity.
//
//   Feedback feedback(verbosity_of(*cmd));          // in the command's callback
//   Progress progress = feedback.progress();         // draws nothing for the first second
//   for (...) progress.tick([&] { return "line " + std::to_string(n); });   // cheap, call often
//   progress.set("recognising features");           // a phase without ticks
//   progress.stop();                                 // before printing anything else
//   feedback.detail("read 3 tools from tools.json"); // -v only
//   feedback.summary("plate.stp: CC2, 6 features, 9 workingsteps, 0.2 s");   // not with -q
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace CLI {
class App;
}

namespace ncbridge::cli {

enum class Verbosity { Quiet, Normal, Verbose };

// -q/--quiet and -v/--verbose, given before or after the command's name (the command's own
// -q, as diff's, counts too).
Verbosity verbosity_of(const CLI::App& command);

// A line on stderr, redrawn in place while the work goes on: only when stderr is a terminal,
// only after the first second, at most five times a second (a thread draws it, so a phase that
// does not tick still shows). Stopped and erased by stop() or the destructor.
class Progress {
 public:
  explicit Progress(bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  template <typename MakeText>
  void tick(MakeText&& make_text) {
    if (enabled_ && (++ticks_ & 0x3FFF) == 0) set(make_text());
  }
  void set(std::string text);
  void stop();
  bool enabled() const { return enabled_; }

 private:
  void draw_loop(std::stop_token stop);

  bool enabled_;
  std::uint64_t ticks_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable_any wake_;  // stop() wakes the drawer at once
  std::string text_;
  bool shown_ = false;
  std::jthread drawer_;
};

class Feedback {
 public:
  // Each command's callback: Feedback feedback(verbosity_of(*cmd)).
  explicit Feedback(Verbosity verbosity);
  Verbosity verbosity() const { return verbosity_; }
  // "ncbridge: TEXT" on stderr, unless -q.
  void summary(std::string_view text) const;
  void info(std::string_view text) const { summary(text); }
  // "ncbridge: TEXT" on stderr with -v only.
  void detail(std::string_view text) const;
  // A progress line (enabled on a terminal, unless -q).
  bool progress_wanted() const;
  // Seconds since this Feedback was made (the run's time in summaries).
  double elapsed_s() const;

 private:
  Verbosity verbosity_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace ncbridge::cli
