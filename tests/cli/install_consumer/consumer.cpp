// Interprets a program, builds its CC1 model and writes it as Part 21 text, through the
// installed libraries: prints the canonical calls, workingsteps and bytes.
#include <cstdio>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

int main(int argc, char** argv) {
  if (argc != 4) return 2;
  ncbridge::cc1_builder::Options options;
  options.tools = ncbridge::setup::read_tool_list(argv[2]);
  options.stock = ncbridge::setup::read_stock(argv[3]);
  ncbridge::interpreter::Options interp;
  interp.tools = options.tools;
  ncbridge::cc1_builder::Cc1Builder builder(options);
  ncbridge::interpreter::interpret_file(argv[1], interp, builder);
  const auto project = builder.take_project();
  const std::string text = ncbridge::step_writer::write_stepnc(project);
  std::printf("%llu calls, %zu elements, %zu bytes\n", static_cast<unsigned long long>(builder.calls_seen()),
              project.main_workplan.its_elements.size(), text.size());
  return 0;
}
