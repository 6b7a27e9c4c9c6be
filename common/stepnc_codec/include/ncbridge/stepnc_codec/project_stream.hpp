#pragma once
// A project as a sequence of parts, for the workingsteps and features topics, so a model never
// crosses the bus as one huge sample and its reader can decode it as it arrives:
//  - the shell: everything but the workplan elements, features and operations (ids, workpiece,
//    rawpiece, setup, tools, technologies, machine functions);
//  - chunks: the next workplan elements, in order, with the features and operations that they
//    are the first to name (so every reference of a chunk points into what came before or with
//    it), about `chunk_bytes` each; an element is never split, so a chunk holds at least one.
// Joining the parts gives back a project equal to the one split (ProjectJoiner).
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::stepnc_codec {

struct ProjectParts {
  std::string shell;
  std::vector<std::string> chunks;  // at least one (possibly empty) chunk
};

ProjectParts split_project(const stepnc::Project& project, std::size_t chunk_bytes = std::size_t{1} << 20);

// Reads the parts back in order. Every method throws ncbridge::InputError ("<stepnc model>",
// column = byte offset + 1) on bytes that are not such a part, on a chunk before the shell, and on
// an element naming a feature or operation that did not come before or with it.
class ProjectJoiner {
 public:
  void shell(std::string_view bytes);
  void chunk(std::string_view bytes);
  bool has_shell() const { return has_shell_; }
  std::size_t elements() const { return project_.main_workplan.its_elements.size(); }
  stepnc::Project take();  // the joined project; the joiner is empty after

 private:
  stepnc::Project project_;
  bool has_shell_ = false;
};

// Streamed CC1: workplan elements as a builder hands them on (cc1_builder::WorkplanSink), before
// the project's shell is known. An element chunk holds the workpiece and rawpiece, the tools,
// technologies and machine functions added since the previous chunk (the tables only grow), and
// the elements, each machining workingstep with its own feature and operation (index 0).
class ElementChunker {
 public:
  void element(const stepnc::Project& project, const stepnc::Executable& element);
  std::size_t elements() const { return elements_; }
  std::size_t bytes() const { return body_.size(); }
  // The chunk of the elements since the last one; `project` is the builder's current project.
  std::string take_chunk(const stepnc::Project& project);

 private:
  std::string body_;
  std::size_t elements_ = 0;
  std::size_t tools_sent_ = 0, technologies_sent_ = 0, machine_functions_sent_ = 0;
};

// Reads element chunks in order and hands each element on with a project that holds what it
// names, as the builder did. Throws InputError ("<stepnc model>") on bytes that are not such a
// chunk or an element naming what has not come.
class ElementUnchunker {
 public:
  using ElementFn = std::function<void(const stepnc::Project&, const stepnc::Executable&)>;
  void chunk(std::string_view bytes, const ElementFn& each);
  std::size_t elements() const { return elements_; }

 private:
  stepnc::Project project_;
  std::size_t elements_ = 0;
};

}  // namespace ncbridge::stepnc_codec
