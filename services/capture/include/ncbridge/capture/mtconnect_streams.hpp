#pragma once
// MTConnect (ANSI/MTC1.4 and later, Part 1 and Part 3): an agent's /current and /sample
// answers are MTConnectStreams documents, an error is an MTConnectError document. Only what
// capture needs is read: the header's sequence numbers and every observation's device, element
// name (Execution, Program, Block, LineNumber, ...), subType and value.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::capture {

struct MtconnectObservation {
  std::uint64_t sequence = 0;
  std::string device;      // the DeviceStream's name
  std::string name;        // the element: Execution, Program, Block, Line, LineNumber, ControllerMode, ...
  std::string sub_type;    // e.g. ABSOLUTE / INCREMENTAL for LineNumber
  std::string value;       // the text; "UNAVAILABLE" when the agent has none
  friend bool operator==(const MtconnectObservation&, const MtconnectObservation&) = default;
};

struct MtconnectStreams {
  std::uint64_t instance_id = 0;     // changes when the agent restarts (sequence numbers restart)
  std::uint64_t first_sequence = 0;  // the oldest observation still in the agent's buffer
  std::uint64_t next_sequence = 0;   // where the next /sample?from= should start
  std::uint64_t last_sequence = 0;
  std::vector<MtconnectObservation> observations;  // in sequence order
};

// Throws InputError (file "<mtconnect>") on a document that is not MTConnectStreams; for an
// MTConnectError the message holds the agent's error codes and texts.
MtconnectStreams parse_mtconnect_streams(std::string_view xml);

}  // namespace ncbridge::capture
