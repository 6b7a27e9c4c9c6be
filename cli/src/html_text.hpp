#pragma once
// Text for the HTML pages (html_report, optimize_html): escaped content and short numbers.
#include <string>
#include <string_view>

namespace ncbridge::cli {

// `s` with & < > " as HTML entities.
std::string html_escape(std::string_view s);
// `v` with at most `decimals` decimals, trailing zeros dropped, no "-0".
std::string short_number(double v, int decimals = 3);

}  // namespace ncbridge::cli
