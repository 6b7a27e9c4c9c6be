#include "usage_errors.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <sstream>

namespace ncbridge::cli {

namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

const CLI::App* subcommand_named(const CLI::App& app, const std::string& word) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->check_name(word)) return sub;
  }
  return nullptr;
}

// The commands argv names, outermost first ("capture", then "linuxcnc"): each word that is not
// an option and names a subcommand of the one before; empty when the first such word names none.
std::vector<const CLI::App*> command_chain(const CLI::App& app, int argc, const char* const* argv) {
  std::vector<const CLI::App*> chain;
  const CLI::App* current = &app;
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.starts_with("-")) continue;
    const CLI::App* sub = subcommand_named(*current, word);
    if (sub == nullptr) break;
    chain.push_back(sub);
    current = sub;
  }
  return chain;
}

const CLI::App* named_command(const CLI::App& app, int argc, const char* const* argv) {
  const auto chain = command_chain(app, argc, argv);
  return chain.empty() ? nullptr : chain.front();
}

std::vector<std::string> option_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* o : command.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// The words CLI11 did not expect, from its message "... not expected: A B".
std::vector<std::string> unexpected_words(const std::string& message) {
  std::vector<std::string> words;
  const auto colon = message.find(": ");
  if (colon == std::string::npos) return words;
  std::istringstream in(message.substr(colon + 2));
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

bool is_number(std::string_view word) {
  double value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  return ec == std::errc() && end == word.data() + word.size();
}

// "unknown option --outptu (did you mean --output?)" for each option word that neither the
// program nor the commands argv names have (CLI11 would first complain about a required option
// the typo was meant to be).
std::string unknown_options(const CLI::App& app, const std::vector<const CLI::App*>& chain, int argc,
                            const char* const* argv) {
  std::vector<std::string> known = option_names(app);
  for (const CLI::App* command : chain) {
    const std::vector<std::string> own = option_names(*command);
    known.insert(known.end(), own.begin(), own.end());
  }
  std::string text;
  bool in_command = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "--") break;
    if (!in_command) {
      in_command = !word.starts_with("-");
      continue;
    }
    if (!word.starts_with("-") || word == "-" || is_number(word)) continue;
    const std::string flag(word.starts_with("--") ? word.substr(0, word.find('=')) : word.substr(0, 2));
    if (std::find(known.begin(), known.end(), flag) != known.end()) continue;
    std::string part = "unknown option " + flag;
    if (const auto near = nearest(flag, known)) part += " (did you mean " + *near + "?)";
    text += (text.empty() ? "" : "; ") + part;
  }
  return text;
}

}  // namespace

std::optional<std::string> nearest(std::string_view word, const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  if (word.size() <= 2) return best;  // "-x": every short option is as near
  const std::size_t near_enough = std::max<std::size_t>(1, word.size() / 3);
  std::size_t best_distance = 0;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    const bool prefix = word.size() >= 3 && c.starts_with(word);  // "conv" for "convert"
    if ((d <= near_enough || prefix) && (!best || d < best_distance)) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::optional<std::string> command_error(const CLI::App& app, int argc, const char* const* argv) {
  const std::vector<std::string> names = command_names(app);
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "-h" || word == "--help" || word == "--version") return std::nullopt;
    if (word.starts_with("-")) continue;
    if (named_command(app, argc, argv) != nullptr) return std::nullopt;
    std::string message = "unknown command '" + word + "'";
    if (const auto near = nearest(word, names)) message += " (did you mean '" + *near + "'?)";
    return message + "; the commands are " + joined(names) + " (see ncbridge --help)";
  }
  return "no command given; the commands are " + joined(names) + " (see ncbridge --help)";
}

std::string parse_error_message(const CLI::App& app, const CLI::ParseError& e, int argc, const char* const* argv) {
  const auto chain = command_chain(app, argc, argv);
  const CLI::App* command = chain.empty() ? nullptr : chain.back();
  std::string name;
  for (const CLI::App* c : chain) name += (name.empty() ? "" : " ") + c->get_name();
  const std::string prefix = name.empty() ? "" : name + ": ";
  const std::string help = name.empty() ? "ncbridge --help" : "ncbridge " + name + " --help";
  std::string message = unknown_options(app, chain, argc, argv);
  if (!message.empty()) return prefix + message + " (see " + help + ")";
  message = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    std::string text;
    for (const std::string& word : unexpected_words(message)) {
      std::string part;
      if (word.starts_with("-")) {
        const std::string flag = word.substr(0, word.find('='));
        part = "unknown option " + flag;
        if (const auto near = nearest(flag, option_names(command ? *command : app))) part += " (did you mean " + *near + "?)";
      } else {
        part = "unexpected argument '" + word + "'";
      }
      text += (text.empty() ? "" : "; ") + part;
    }
    if (!text.empty()) message = text;
  }
  return prefix + message + " (see " + help + ")";
}

}  // namespace ncbridge::cli
