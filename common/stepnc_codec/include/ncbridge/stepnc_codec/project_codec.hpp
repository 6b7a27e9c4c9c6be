#pragma once
// The ISO 14649 model of a job (stepnc::Project, CC1 or CC2) as bytes and back, losslessly:
// every attribute of every entity, doubles as their IEEE-754 bits, SourceLines included, so
// decode(encode(p)) == p and the step_writer writes the same file from either. This is the
// `model` of the workingsteps and features topics (proto/workingsteps.proto).
//
// Layout: "NCBM", a format version, then the project's fields in declaration order
// (little-endian fixed-width numbers, length-prefixed strings and sequences, one byte for
// optionals and variant alternatives).
#include <string>
#include <string_view>

#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::stepnc_codec {

std::string encode_project(const stepnc::Project& project);

// Throws ncbridge::InputError (file "<stepnc model>", column = byte offset + 1) when the bytes
// are not an encoded project: wrong magic or version, truncated, a count larger than the rest
// of the bytes, an enumerator or variant alternative out of range, trailing bytes.
stepnc::Project decode_project(std::string_view bytes);

}  // namespace ncbridge::stepnc_codec
