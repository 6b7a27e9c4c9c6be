#pragma once
// Evaluation of the block model's expression trees, with LinuxCNC's semantics: angles in
// degrees, EQ/NE within 1e-4, FIX = floor, FUP = ceiling, ROUND half away from zero, MOD
// with a non-negative result, AND/OR/XOR on "non-zero".
#include <functional>
#include <string>

#include "block_model.hpp"
#include "parameters.hpp"

namespace ncbridge::interpreter {

// Throws InputError (file, block.line, the node's column) on a domain error, a division by
// zero or an undefined parameter.
double evaluate(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file);

// Custom macro B (Fanuc): a numbered variable may be vacant (#0 always is); `vacant(n)` says which.
// A vacant variable reads 0 in arithmetic and in GT/GE/LT/LE, while EQ and NE tell it from 0
// (vacant EQ vacant is true, vacant EQ 0 false).
using VacantTest = std::function<bool(int number)>;
double evaluate(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file,
                const VacantTest& vacant);
// True when `ref` is a lone reference to a vacant variable (#1 or [#1]): what an assignment copies
// as vacant and an address word with it leaves out.
bool vacant_reference(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file,
                      const VacantTest& vacant);

// The parameter number of a Parameter node, checked to be in range.
int parameter_number(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file);

}  // namespace ncbridge::interpreter
