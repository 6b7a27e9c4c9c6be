#include "listing.hpp"

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <stdexcept>

#include "ncbridge/interpreter/canon_printer.hpp"

namespace ncbridge::testing {

namespace {

class Tee final : public canonical::Sink {
 public:
  Tee(canonical::Sink& a, canonical::Sink* b) : a_(a), b_(b) {}
  void source_file(std::uint32_t index, std::string_view path) override {
    a_.source_file(index, path);
    if (b_ != nullptr) b_->source_file(index, path);
  }
  void call(const canonical::Call& c) override {
    a_.call(c);
    if (b_ != nullptr) b_->call(c);
  }
  void end() override {
    a_.end();
    if (b_ != nullptr) b_->end();
  }

 private:
  canonical::Sink& a_;
  canonical::Sink* b_;
};

std::string listing_of(const std::function<void(canonical::Sink&)>& interpret, canonical::Sink* also) {
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* memory = open_memstream(&buffer, &size);
  if (memory == nullptr) throw std::runtime_error("open_memstream failed");
  std::string text;
  try {
    {
      interpreter::CanonPrinter printer(memory);
      Tee tee(printer, also);
      interpret(tee);
      printer.flush();
    }
    std::fclose(memory);
    text.assign(buffer, size);
    std::free(buffer);
  } catch (...) {
    std::fclose(memory);
    std::free(buffer);
    throw;
  }
  return text;
}

}  // namespace

std::string canon_listing(const std::filesystem::path& program, const interpreter::Options& options,
                          canonical::Sink* also) {
  return listing_of([&](canonical::Sink& sink) { interpreter::interpret_file(program, options, sink); }, also);
}

std::string canon_listing_of_text(std::string_view text, const std::string& name, const interpreter::Options& options) {
  return listing_of([&](canonical::Sink& sink) { interpreter::interpret_text(text, name, options, sink); }, nullptr);
}

}  // namespace ncbridge::testing
