#pragma once
// Programs read in this process, printed as `ncbridge canon` prints them.
#include <filesystem>
#include <string>
#include <string_view>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/interpreter/interpreter.hpp"

namespace ncbridge::testing {

// The listing of a program file; its calls also go to `also` (source_file, call..., end) when
// given. Throws what the interpreter (or `also`) throws.
std::string canon_listing(const std::filesystem::path& program, const interpreter::Options& options,
                          canonical::Sink* also = nullptr);
// The same for program text; `name` names it in errors.
std::string canon_listing_of_text(std::string_view text, const std::string& name, const interpreter::Options& options);

}  // namespace ncbridge::testing
