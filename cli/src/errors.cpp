#include "errors.hpp"

#include <cstdio>
#include <new>
#include <system_error>

namespace ncbridge::cli {

namespace {

std::string located(std::string_view severity, const SourceLocation& where, std::string_view message) {
  std::string line = "ncbridge: ";
  line += severity;
  line += ": ";
  if (!where.file.empty()) line += where.to_string() + ": ";
  line += message;
  return line;
}

void print_line(const std::string& line) {
  std::fflush(stdout);  // what the command printed comes first
  std::fprintf(stderr, "%s\n", line.c_str());
}

}  // namespace

OutputError::OutputError(std::filesystem::path path, const std::string& message)
    : std::runtime_error(path.string() + ": " + message), path_(std::move(path)), message_(message) {}

std::string error_line(const SourceLocation& where, std::string_view message) { return located("error", where, message); }

std::string warning_line(const SourceLocation& where, std::string_view message) {
  return located("warning", where, message);
}

void print_error(const SourceLocation& where, std::string_view message) { print_line(error_line(where, message)); }

void print_error(std::string_view message) { print_line(error_line({}, message)); }

void print_error(const InputError& e) {
  SourceLocation where = e.where();
  if (where.file.empty() && where.line != 0) where.file = "<input>";
  print_error(where, e.message());
}

void print_warning(const SourceLocation& where, std::string_view message) { print_line(warning_line(where, message)); }

int report_exception(std::exception_ptr e) {
  try {
    std::rethrow_exception(e);
  } catch (const InputError& error) {
    print_error(error);
    return exit_status::input_error;
  } catch (const OutputError& error) {
    print_error({error.path().string(), 0, 0}, error.message());
    return exit_status::output_error;
  } catch (const UsageError& error) {
    print_error(error.what());
    return exit_status::usage_error;
  } catch (const ServiceUnavailable& error) {
    print_error(error.what());
    return exit_status::service_unavailable;
  } catch (const std::bad_alloc&) {
    print_error("out of memory");
    return exit_status::internal_error;
  } catch (const std::system_error& error) {  // a file or the system refused (our own outputs are OutputError)
    print_error(error.what());
    return exit_status::output_error;
  } catch (const std::exception& error) {
    print_error(std::string("internal error: ") + error.what() + " (please report this)");
    return exit_status::internal_error;
  } catch (...) {
    print_error("internal error: unknown exception (please report this)");
    return exit_status::internal_error;
  }
}

}  // namespace ncbridge::cli
