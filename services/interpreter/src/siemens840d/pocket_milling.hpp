#pragma once
// SINUMERIK POCKET3 (rectangular pocket) and POCKET4 (circular pocket), decomposed into moves:
// layer by layer down to the depth (equal infeeds of at most MID, plunged vertically at FFD), in
// each layer contour-parallel rings from the inside out (ring spacing MIDA, or 80 % of the tool
// diameter when MIDA is 0) to the pocket wall less the tool radius and the allowance FAL, then
// back to the plunge point; finally up to RFP + SDIS and RTP. Roughing (VARI units digit 1)
// leaves FAL on the wall and FALD on the base; finishing (2) runs the same rings to the final
// size. CDIR: 0 climb, 1 conventional (for the spindle direction), 2 G2, 3 G3.
#include <cstdint>
#include <map>
#include <string>

#include "lowering/dialect_machine.hpp"

namespace ncbridge::interpreter::siemens840d {

// `args`: the cycle's parameters by name (without the leading underscore); `tool_radius` in
// program units. Errors name the cycle and are located at `column` of the current block.
void rectangular_pocket(lowering::DialectMachine& m, const std::string& name, const std::map<std::string, double>& args,
                        double tool_radius, std::uint32_t column);
void circular_pocket(lowering::DialectMachine& m, const std::string& name, const std::map<std::string, double>& args,
                     double tool_radius, std::uint32_t column);

}  // namespace ncbridge::interpreter::siemens840d
