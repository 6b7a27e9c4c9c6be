#include "expression.hpp"

#include <cmath>
#include <numbers>

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kEqualTolerance = 1e-4;

class Evaluator {
 public:
  Evaluator(const Block& b, const Parameters& p, const std::string& f, const VacantTest* vacant = nullptr)
      : b_(b), p_(p), f_(f), vacant_(vacant) {}

  [[noreturn]] void fail(const ExprNode& n, const std::string& message) const {
    throw InputError({f_, b_.line, n.column}, message);
  }

  int number_of(const ExprNode& n) const {
    double v = eval(n.a);
    if (vacant_ != nullptr && v == 0.0) return 0;  // #0: always vacant
    if (!Parameters::valid_number(v)) fail(n, "Parameter number out of range");
    return static_cast<int>(std::lround(v));
  }

  double eval(ExprRef ref) const {
    const ExprNode& n = b_.nodes[ref];
    switch (n.op) {
      case ExprOp::Number: return n.value;
      case ExprOp::Parameter: {
        const int number = number_of(n);
        if (vacant_ != nullptr && (*vacant_)(number)) return 0.0;
        return p_.numbered(number);
      }
      case ExprOp::NamedParameter: {
        auto name = b_.name(n.name_begin, n.name_length);
        auto v = p_.named(name);
        if (!v) fail(n, "Named parameter #<" + std::string(name) + "> not defined");
        return *v;
      }
      case ExprOp::Exists: return p_.exists(b_.name(n.name_begin, n.name_length)) ? 1.0 : 0.0;
      default: break;
    }
    double a = eval(n.a);
    switch (n.op) {
      case ExprOp::Negate: return -a;
      case ExprOp::Abs: return std::fabs(a);
      case ExprOp::Acos:
        if (a < -1.0 || a > 1.0) fail(n, "Argument to ACOS out of range");
        return std::acos(a) / kDegree;
      case ExprOp::Asin:
        if (a < -1.0 || a > 1.0) fail(n, "Argument to ASIN out of range");
        return std::asin(a) / kDegree;
      case ExprOp::Cos: return std::cos(a * kDegree);
      case ExprOp::Exp: return std::exp(a);
      case ExprOp::Fix: return std::floor(a);
      case ExprOp::Fup: return std::ceil(a);
      case ExprOp::Round: return std::round(a);
      case ExprOp::Ln:
        if (a <= 0.0) fail(n, "Zero or negative argument to LN");
        return std::log(a);
      case ExprOp::Sin: return std::sin(a * kDegree);
      case ExprOp::Sqrt:
        if (a < 0.0) fail(n, "Negative argument to SQRT");
        return std::sqrt(a);
      case ExprOp::Tan: return std::tan(a * kDegree);
      case ExprOp::Not: return a == 0.0 ? 1.0 : 0.0;
      default: break;
    }
    double b = eval(n.b);
    switch (n.op) {
      case ExprOp::Atan: return std::atan2(a, b) / kDegree;
      case ExprOp::Power:
        if (a < 0.0 && std::floor(b) != b) fail(n, "Attempt to raise negative to non-integer power");
        return std::pow(a, b);
      case ExprOp::Times: return a * b;
      case ExprOp::Divide:
        if (b == 0.0) fail(n, "Attempt to divide by zero");
        return a / b;
      case ExprOp::Modulo: {
        if (b == 0.0) fail(n, "Attempt to divide by zero");
        double r = std::fmod(a, b);
        if (r < 0.0) r += std::fabs(b);
        return r;
      }
      case ExprOp::Plus: return a + b;
      case ExprOp::Minus: return a - b;
      case ExprOp::Eq:
      case ExprOp::Ne: {
        bool equal = std::fabs(a - b) < kEqualTolerance;
        if (vacant_ != nullptr) {
          const bool va = is_vacant(n.a), vb = is_vacant(n.b);
          if (va || vb) equal = va && vb;
        }
        return (n.op == ExprOp::Eq) == equal ? 1.0 : 0.0;
      }
      case ExprOp::Gt: return a > b ? 1.0 : 0.0;
      case ExprOp::Ge: return a >= b ? 1.0 : 0.0;
      case ExprOp::Lt: return a < b ? 1.0 : 0.0;
      case ExprOp::Le: return a <= b ? 1.0 : 0.0;
      case ExprOp::And: return (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
      case ExprOp::Or: return (a != 0.0 || b != 0.0) ? 1.0 : 0.0;
      case ExprOp::Xor: return ((a != 0.0) != (b != 0.0)) ? 1.0 : 0.0;
      default: break;
    }
    fail(n, "Unknown operation in expression");
  }

  bool is_vacant(ExprRef ref) const {
    const ExprNode& n = b_.nodes[ref];
    return vacant_ != nullptr && n.op == ExprOp::Parameter && (*vacant_)(number_of(n));
  }

 private:
  const Block& b_;
  const Parameters& p_;
  const std::string& f_;
  const VacantTest* vacant_;
};

}  // namespace

double evaluate(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file) {
  return Evaluator(block, parameters, file).eval(ref);
}

double evaluate(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file,
                const VacantTest& vacant) {
  return Evaluator(block, parameters, file, &vacant).eval(ref);
}

bool vacant_reference(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file,
                      const VacantTest& vacant) {
  return Evaluator(block, parameters, file, &vacant).is_vacant(ref);
}

int parameter_number(const Block& block, ExprRef ref, const Parameters& parameters, const std::string& file) {
  Evaluator e(block, parameters, file);
  return e.number_of(block.nodes[ref]);
}

}  // namespace ncbridge::interpreter
