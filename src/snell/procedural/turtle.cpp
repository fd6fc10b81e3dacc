// Turtle interpretation of a module string (ABoP 1990, ch. 1.5; rotations R_U, R_L, R_H of eq. 1.4 written
// as rotations of two frame vectors in their plane).
#include "snell/procedural/turtle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace snell::procedural {

namespace {

struct State {
  TurtleFrame frame;
  /// Index of the segment this state may continue (its end is the current position), or -1.
  long long last_segment = -1;
};

/// Rotates the pair (a, b) by `degrees` in their plane: a moves toward b.
void rotate_pair(Vec3& a, Vec3& b, double degrees) {
  const double r = degrees * std::numbers::pi / 180;
  const double c = std::cos(r), s = std::sin(r);
  const Vec3 na = a * c + b * s;
  const Vec3 nb = b * c - a * s;
  a = na, b = nb;
}

float to_float(double v) {
  return static_cast<float>(v);
}

}  // namespace

TurtleResult interpret(const ModuleString& modules, const TurtleSettings& settings) {
  std::array<char, 256> command{};
  for (int c = 0; c < 256; ++c) command[static_cast<std::size_t>(c)] = static_cast<char>(c);
  for (const auto& [from, to] : settings.aliases) command[static_cast<unsigned char>(from)] = to;

  TurtleResult out;
  State s;
  s.frame = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), settings.width, 0};
  out.lo = out.hi = s.frame.position;
  std::vector<State> stack;
  const auto advance = [&](double length) {
    s.frame.position = s.frame.position + s.frame.heading * length;
    out.lo = min(out.lo, s.frame.position);
    out.hi = max(out.hi, s.frame.position);
  };
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const std::span<const double> p = modules.parameters(i);
    const bool has = !p.empty();
    const double angle = has ? p[0] : settings.angle_degrees;
    TurtleFrame& f = s.frame;
    switch (command[static_cast<unsigned char>(modules.symbol(i))]) {
      case 'F': {
        const Vec3 a = f.position;
        advance(has ? p[0] : settings.step);
        const float r = to_float(f.width / 2);
        if (s.last_segment >= 0) out.segments[static_cast<std::size_t>(s.last_segment)].r1 = r;
        out.segments.push_back({{to_float(a.x), to_float(a.y), to_float(a.z)},
                                {to_float(f.position.x), to_float(f.position.y), to_float(f.position.z)},
                                r,
                                r,
                                static_cast<std::uint16_t>(std::clamp(f.colour, 0, 65535))});
        s.last_segment = static_cast<long long>(out.segments.size()) - 1;
        break;
      }
      case 'f':
        advance(has ? p[0] : settings.step);
        s.last_segment = -1;
        break;
      case '+':
        rotate_pair(f.heading, f.left, angle);
        break;
      case '-':
        rotate_pair(f.heading, f.left, -angle);
        break;
      case '&':
        rotate_pair(f.heading, f.up, -angle);
        break;  // heading dips away from up
      case '^':
        rotate_pair(f.heading, f.up, angle);
        break;
      case '\\':
        rotate_pair(f.left, f.up, angle);
        break;
      case '/':
        rotate_pair(f.left, f.up, -angle);
        break;
      case '|':
        rotate_pair(f.heading, f.left, 180);
        break;
      case '[':
        stack.push_back(s);
        s.frame.width *= settings.taper;
        s.last_segment = -1;
        break;
      case ']':
        if (stack.empty()) throw LSystemError("']' without a matching '[' in the generated string");
        s = stack.back();
        stack.pop_back();  // the parent's last segment may still be continued
        break;
      case '!':
        f.width = has ? p[0] : f.width * settings.taper;
        break;
      case '\'':
        f.colour = has ? static_cast<int>(p[0]) : f.colour + 1;
        break;
      case '~':
        out.leaves.push_back(f);
        break;
      default:
        break;
    }
  }
  out.end = s.frame;
  return out;
}

}  // namespace snell::procedural
