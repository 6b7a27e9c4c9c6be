#include "feedback.hpp"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cstdio>

namespace ncbridge::cli {

namespace {

using Clock = std::chrono::steady_clock;

constexpr auto kQuietFor = std::chrono::seconds(1);
constexpr auto kRedrawEvery = std::chrono::milliseconds(200);

std::size_t flag_count(const CLI::App& app, const std::string& name) {
  const CLI::Option* option = app.get_option_no_throw(name);
  return option ? option->count() : 0;
}

}  // namespace

Verbosity verbosity_of(const CLI::App& command) {
  std::size_t quiet = 0, verbose = 0;
  for (const CLI::App* app = &command; app != nullptr; app = app->get_parent()) {
    quiet += flag_count(*app, "--quiet");
    verbose += flag_count(*app, "--verbose");
  }
  if (quiet > 0) return Verbosity::Quiet;
  return verbose > 0 ? Verbosity::Verbose : Verbosity::Normal;
}

// ---- Progress ----

Progress::Progress(bool enabled) : enabled_(enabled), start_(Clock::now()) {
  if (enabled_) drawer_ = std::jthread([this](std::stop_token stop) { draw_loop(stop); });
}

Progress::~Progress() { stop(); }

void Progress::set(std::string text) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  text_ = std::move(text);
}

void Progress::draw_loop(std::stop_token stop) {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, stop, kRedrawEvery, [&] { return stop.stop_requested(); })) {
    if (Clock::now() - start_ < kQuietFor || text_.empty()) continue;
    std::fprintf(stderr, "\r%s\033[K", text_.c_str());
    std::fflush(stderr);
    shown_ = true;
  }
}

void Progress::stop() {
  if (!enabled_) return;
  if (drawer_.joinable()) {
    drawer_.request_stop();
    drawer_.join();
  }
  const std::lock_guard lock(mutex_);
  if (shown_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  }
  shown_ = false;
}

// ---- Feedback ----

Feedback::Feedback(Verbosity verbosity) : verbosity_(verbosity), start_(Clock::now()) {}

void Feedback::summary(std::string_view text) const {
  if (verbosity_ == Verbosity::Quiet) return;
  std::fprintf(stderr, "ncbridge: %.*s\n", static_cast<int>(text.size()), text.data());
}

void Feedback::detail(std::string_view text) const {
  if (verbosity_ != Verbosity::Verbose) return;
  std::fprintf(stderr, "ncbridge: %.*s\n", static_cast<int>(text.size()), text.data());
}

bool Feedback::progress_wanted() const { return verbosity_ != Verbosity::Quiet && isatty(STDERR_FILENO) != 0; }

double Feedback::elapsed_s() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

}  // namespace ncbridge::cli
