#pragma once
// Evaluation of the block model's expression trees, with LinuxCNC's semantics: angles in
// degrees, EQ/NE within 1e-4, FIX = floor, FUP = ceiling, ROUND half away from zero, MOD
// with a non-negative result, AND/OR/XOR on "non-zero".
#include <string>

#include "block_model.hpp"
#include "parameters.hpp"

namespace ncbridge::interpreter {

// Throws InputError (file, block.line, the node's column) on a domain error, a division by
// zero or an undefined parameter.
double evaluate(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file);

// The parameter number of a Parameter node, checked to be in range.
int parameter_number(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file);

}  // namespace ncbridge::interpreter
