#pragma once
// A CC1 Part 21 file written while its workplan is being built: the header, the workpiece, then
// each finished workplan element (workingstep or rapid movement, with its toolpaths),
// then the setup, WORKPLAN and PROJECT. Only the instance ids of the elements are kept, so memory
// does not grow with the program. The bytes are those write_stepnc (stepnc_file.hpp) writes for
// the whole project, provided each streamed workingstep's feature and operation are its own
// (as the cc1_builder makes them) and every element's security plane is the setup's.
#include <cstdint>
#include <functional>
#include <memory>
#include <string_view>

#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::step_writer {

class StepncStreamWriter {
 public:
  // `write_chunk` gets the text in pieces of about 1 MB.
  StepncStreamWriter(const StepncWriteOptions& options, std::function<void(std::string_view)> write_chunk);
  ~StepncStreamWriter();
  StepncStreamWriter(const StepncStreamWriter&) = delete;
  StepncStreamWriter& operator=(const StepncStreamWriter&) = delete;

  // Writes one finished element (the first one after project.rawpiece and project.workpiece,
  // which must not change afterwards). `project` holds the tools, technologies and machine functions
  // it names and, for a machining workingstep, its feature and operation at the indices it
  // names; it is read during the call only. The element's its_secplane is ignored: it refers to
  // the setup's security plane, written by finish().
  void element(const stepnc::Project& project, const stepnc::Executable& element);

  // Writes the SETUP (with the security plane), the WORKPLAN of every element written and the
  // PROJECT (project.setup, project.its_id, project.main_workplan.its_id); returns the size of
  // the whole text in bytes.
  std::uint64_t finish(const stepnc::Project& project);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncbridge::step_writer
