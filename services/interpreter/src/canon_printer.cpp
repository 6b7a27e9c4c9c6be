#include "ncbridge/interpreter/canon_printer.hpp"

#include <charconv>
#include <string_view>
#include <type_traits>

#include "decimal_text.hpp"

namespace ncbridge::interpreter {

namespace {

using namespace canonical;

constexpr std::size_t kFlushAt = 1 << 16;

class Out {
 public:
  explicit Out(std::string& s) : s_(s) {}
  Out& operator<<(std::string_view text) { s_.append(text); return *this; }
  Out& operator<<(char c) { s_.push_back(c); return *this; }
  Out& real(double v, int precision = 4) {
    append_fixed(s_, v, precision);
    return *this;
  }
  Out& integer(long long v) {
    char tmp[24];
    auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
    s_.append(tmp, r.ptr);
    return *this;
  }
  // ", " separated reals
  Out& reals(std::initializer_list<double> values) {
    bool first = true;
    for (double v : values) {
      if (!first) s_.append(", ");
      first = false;
      real(v);
    }
    return *this;
  }

 private:
  std::string& s_;
};

std::string_view plane_name(Plane p) {
  switch (p) {
    case Plane::XY: return "CANON_PLANE_XY";
    case Plane::YZ: return "CANON_PLANE_YZ";
    case Plane::XZ: return "CANON_PLANE_XZ";
    case Plane::UV: return "CANON_PLANE_UV";
    case Plane::VW: return "CANON_PLANE_VW";
    case Plane::UW: return "CANON_PLANE_UW";
  }
  return "UNKNOWN";
}

void print_pose6(Out& o, const Pose& p) { o.reals({p.x, p.y, p.z, p.a, p.b, p.c}); }

void format(Out& o, const Data& data, Units units) {
  if (const auto* print = std::get_if<Print>(&data)) {  // rs274: the bare text
    o << print->text;
    return;
  }
  // rs274 spells this one without the final H
  if (std::holds_alternative<StartSpeedFeedSynch>(data)) {
    o << "START_SPEED_FEED_SYNC";
  } else if (const auto* wait = std::get_if<WaitSpindleOrientComplete>(&data)) {
    o << "SPINDLE.";  // rs274: SPINDLE.<n>.WAIT_ORIENT_COMPLETE(timeout)
    o.integer(wait->spindle) << ".WAIT_ORIENT_COMPLETE";
  } else {
    o << name_of(data);
  }
  o << '(';
  std::visit(
      [&o, units](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, UseLengthUnits>) {
          o << (d.units == Units::Inches ? "CANON_UNITS_INCHES" : "CANON_UNITS_MM");
        } else if constexpr (std::is_same_v<T, SetG5xOffset>) {
          o.integer(d.index) << ", ";
          print_pose6(o, d.offset);
        } else if constexpr (std::is_same_v<T, SetG92Offset>) {
          print_pose6(o, d.offset);
        } else if constexpr (std::is_same_v<T, SetXyRotation>) {
          o.real(d.degrees);
        } else if constexpr (std::is_same_v<T, SelectPlane>) {
          o << plane_name(d.plane);
        } else if constexpr (std::is_same_v<T, SetTraverseRate> || std::is_same_v<T, SetFeedRate>) {
          o.real(d.rate);
        } else if constexpr (std::is_same_v<T, StraightTraverse> || std::is_same_v<T, StraightFeed> ||
                             std::is_same_v<T, StraightProbe>) {
          print_pose6(o, d.end);
        } else if constexpr (std::is_same_v<T, SetFeedReference>) {
          o << (d.reference == FeedReference::Workpiece ? "CANON_WORKPIECE" : "CANON_XYZ");
        } else if constexpr (std::is_same_v<T, SetFeedMode>) {
          o.integer(d.spindle) << ", ";
          o.integer(d.mode);
        } else if constexpr (std::is_same_v<T, SetMotionControlMode>) {
          switch (d.mode) {
            case MotionControlMode::ExactStop: o << "CANON_EXACT_STOP"; break;
            case MotionControlMode::ExactPath: o << "CANON_EXACT_PATH"; break;
            case MotionControlMode::Continuous:
              o << "CANON_CONTINUOUS, ";
              o.real(d.tolerance, 6);
              break;
          }
        } else if constexpr (std::is_same_v<T, SetNaivecamTolerance>) {
          o.real(d.tolerance);
        } else if constexpr (std::is_same_v<T, SetCutterRadiusCompensation>) {
          o.real(d.radius);
        } else if constexpr (std::is_same_v<T, StartCutterRadiusCompensation>) {
          o << (d.side == Side::Left ? "LEFT" : d.side == Side::Right ? "RIGHT" : "UNKNOWN");
        } else if constexpr (std::is_same_v<T, StartSpeedFeedSynch>) {
          o.real(d.feed_per_revolution, 6) << ',';
          o.integer(d.velocity_mode ? 1 : 0);
        } else if constexpr (std::is_same_v<T, ArcFeed>) {
          o.reals({d.first_end, d.second_end, d.first_axis, d.second_axis}) << ", ";
          o.integer(d.rotation) << ", ";
          o.reals({d.axis_end_point, d.a, d.b, d.c});
        } else if constexpr (std::is_same_v<T, RigidTap>) {
          o.reals({d.end.x, d.end.y, d.end.z});
        } else if constexpr (std::is_same_v<T, Dwell>) {
          o.real(d.seconds);
        } else if constexpr (std::is_same_v<T, SetSpindleSpeed>) {
          o.integer(d.spindle) << ", ";
          o.real(d.rpm);
        } else if constexpr (std::is_same_v<T, StartSpindleClockwise> ||
                             std::is_same_v<T, StartSpindleCounterclockwise> ||
                             std::is_same_v<T, StopSpindleTurning> ||
                             std::is_same_v<T, EnableSpeedOverride> ||
                             std::is_same_v<T, DisableSpeedOverride>) {
          o.integer(d.spindle);
        } else if constexpr (std::is_same_v<T, SetSpindleMode>) {
          o.integer(d.spindle) << ' ';
          o.real(d.css_maximum);
        } else if constexpr (std::is_same_v<T, OrientSpindle>) {
          o.integer(d.spindle) << ", ";
          o.real(d.orientation) << ", ";
          o.integer(d.mode);
        } else if constexpr (std::is_same_v<T, UseToolLengthOffset>) {
          const Pose& p = d.offset;
          o.real(p.x) << ' ';
          o.real(p.y) << ' ';
          o.real(p.z) << ", ";
          o.real(p.a) << ' ';
          o.real(p.b) << ' ';
          o.real(p.c) << ", ";
          o.real(p.u) << ' ';
          o.real(p.v) << ' ';
          o.real(p.w);
        } else if constexpr (std::is_same_v<T, SelectTool>) {
          o.integer(d.tool);
        } else if constexpr (std::is_same_v<T, ChangeTool>) {
          o.integer(d.slot);
        } else if constexpr (std::is_same_v<T, ChangeToolNumber>) {
          o.integer(d.pocket);  // rs274 prints the pocket index
        } else if constexpr (std::is_same_v<T, SetToolTableEntry>) {
          const double to_inch = units == Units::Millimeters ? 1.0 / 25.4 : 1.0;
          const Pose& p = d.offset;
          o.integer(d.pocket) << ", ";
          o.integer(d.tool) << ", ";
          for (double v : {p.x * to_inch, p.y * to_inch, p.z * to_inch, p.a, p.b, p.c, p.u * to_inch,
                           p.v * to_inch}) {
            o.real(v) << ' ';
          }
          o.real(p.w * to_inch) << ", ";
          o.real(d.frontangle) << ", ";
          o.real(d.backangle) << ", ";
          o.integer(d.orientation);
        } else if constexpr (std::is_same_v<T, WaitSpindleOrientComplete>) {
          o.real(d.timeout);
        } else if constexpr (std::is_same_v<T, NurbsFeed>) {
          o.integer(static_cast<long long>(d.control_points.size())) << ", ...";  // as rs274 prints it
        } else if constexpr (std::is_same_v<T, Comment> || std::is_same_v<T, Message> || std::is_same_v<T, Log>) {
          o << '"' << d.text << '"';
        } else if constexpr (std::is_same_v<T, LogOpen> || std::is_same_v<T, LogAppend>) {
          o << '"' << d.path << '"';
        }
      },
      data);
  o << ')';
}

}  // namespace

CanonPrinter::CanonPrinter(std::FILE* out) : out_(out) { buffer_.reserve(kFlushAt + 4096); }

CanonPrinter::~CanonPrinter() { flush(); }

void CanonPrinter::format_call(const canonical::Data& data, std::string& out, canonical::Units units) {
  out.clear();
  Out o(out);
  format(o, data, units);
}

void CanonPrinter::write_prefix(const canonical::Source& source) {
  char tmp[32];
  // "%5d "
  auto r = std::to_chars(tmp, tmp + sizeof tmp, counter_++);
  auto len = static_cast<std::size_t>(r.ptr - tmp);
  if (len < 5) buffer_.append(5 - len, ' ');
  buffer_.append(tmp, len);
  buffer_.push_back(' ');
  if (source.n_number < 0) {
    buffer_.append("N..... ");
    return;
  }
  buffer_.push_back('N');
  r = std::to_chars(tmp, tmp + sizeof tmp, source.n_number);
  len = static_cast<std::size_t>(r.ptr - tmp);
  std::size_t digits = len;
  if (source.n_digits > len) {
    buffer_.append(source.n_digits - len, '0');
    digits = source.n_digits;
  }
  buffer_.append(tmp, len);
  buffer_.append(digits < 6 ? 6 - digits : 0, ' ');
}

void CanonPrinter::call(const canonical::Call& call) {
  if (!std::holds_alternative<Print>(call.data)) write_prefix(call.source);  // rs274 numbers no PRINT line
  if (const auto* u = std::get_if<UseLengthUnits>(&call.data)) units_ = u->units;
  Out o(buffer_);
  format(o, call.data, units_);
  buffer_.push_back('\n');
  if (buffer_.size() >= kFlushAt) flush();
}

void CanonPrinter::print_driver_reset() {
  canonical::Call reset{canonical::OnReset{}, {}, std::nullopt};
  call(reset);
  call(reset);
}

void CanonPrinter::end() { flush(); }

void CanonPrinter::flush() {
  if (!buffer_.empty()) {
    std::fwrite(buffer_.data(), 1, buffer_.size(), out_);
    buffer_.clear();
  }
  std::fflush(out_);
}

}  // namespace ncbridge::interpreter
