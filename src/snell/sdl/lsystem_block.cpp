// `lsystem { axiom "..." rule "pred" "succ" [probability p] angle A | angle_divisions N iterations n ... }`:
// an L-system (procedural/lsystem.hpp) drawn by the 3D turtle (procedural/turtle.hpp) as one shape of round
// cones per colour index plus a copy of the `leaf` object at every `~`. See docs/procedural.md.
#include <map>
#include <mutex>
#include <sstream>

#include "snell/math/matrix4.hpp"
#include "snell/procedural/turtle.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/sdl/shape_factory.hpp"

namespace snell::sdl {

namespace {

/// What one set of L-system settings produces; shared by every lsystem block with the same settings.
struct GeneratedPlant {
  /// One branch set per colour index (null where the index draws nothing).
  std::vector<std::shared_ptr<const geometry::Shape>> branches;
  std::vector<procedural::TurtleFrame> leaves;
};

/// Plants by the text of their settings. Weak references: a plant lives as long as an object uses it, and
/// a second block with the same settings (a forest in a #while loop) reuses it instead of growing it again.
std::shared_ptr<const GeneratedPlant> cached_plant(const std::string& key,
                                                   const std::function<GeneratedPlant()>& grow) {
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const GeneratedPlant>> cache;
  {
    const std::lock_guard lock(mutex);
    if (auto found = cache[key].lock()) return found;
  }
  auto plant = std::make_shared<const GeneratedPlant>(grow());
  const std::lock_guard lock(mutex);
  std::erase_if(cache, [](const auto& entry) { return entry.second.expired(); });
  cache[key] = plant;
  return plant;
}

GeneratedPlant grow(const procedural::LSystemSettings& lsystem, const procedural::TurtleSettings& turtle) {
  procedural::TurtleResult drawn = procedural::interpret(procedural::generate_lsystem(lsystem), turtle);
  // Exact sizes first, so no vector holds the slack of doubling growth.
  std::vector<std::size_t> counts;
  for (const procedural::TurtleSegment& s : drawn.segments) {
    if (s.colour >= counts.size()) counts.resize(s.colour + 1u, 0);
    ++counts[s.colour];
  }
  std::vector<std::vector<geometry::BranchInput>> by_colour(counts.size());
  for (std::size_t c = 0; c < counts.size(); ++c) by_colour[c].reserve(counts[c]);
  for (const procedural::TurtleSegment& s : drawn.segments) {
    by_colour[s.colour].push_back(
        {math::Vec3(s.a[0], s.a[1], s.a[2]), math::Vec3(s.b[0], s.b[1], s.b[2]), s.r0, s.r1});
  }
  drawn.segments = {};  // each copy is freed once it is used: a million branches pass through three forms
  GeneratedPlant plant;
  for (auto& branches : by_colour) {
    plant.branches.push_back(branches.empty() ? nullptr : shapes::branch_set(branches));
    branches = {};
  }
  plant.leaves = drawn.leaves;
  return plant;
}

/// The leaf's own space in the turtle's frame: +y along the heading, +x to the left, +z = -up (so the
/// frame stays right-handed like x, y, z).
math::Transform leaf_placement(const procedural::TurtleFrame& f) {
  math::Matrix4 m = math::Matrix4::identity();
  const math::Vec3 columns[4] = {f.left, f.heading, -f.up, f.position};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) m.m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = columns[c][r];
  return math::Transform::from_matrix(m).value_or(math::Transform::translate(f.position));
}

}  // namespace

ParsedObject Parser::parse_lsystem(const Token& keyword) {
  ParsedObject o;
  o.where = keyword.where;
  expect("{", "lsystem");
  procedural::LSystemSettings lsystem;
  procedural::TurtleSettings turtle;
  std::vector<std::shared_ptr<const material::Texture>> palette;
  std::optional<ParsedObject> leaf;
  std::ostringstream key;  // every setting that changes the geometry; scalars are added after the loop
  key.precision(17);
  for (;;) {
    const Token t = peek();
    if (t.is_word("axiom")) {
      raw_next();
      lsystem.axiom = parse_string();
    } else if (t.is_word("rule")) {
      raw_next();
      procedural::LSystemRule rule;
      rule.predecessor = parse_string();
      accept(",");
      rule.successor = parse_string();
      if (peek().is_word("probability")) {
        raw_next();
        rule.probability = parse_float();
      }
      key << "rule\x1f" << rule.predecessor << "\x1f" << rule.successor << "\x1f" << rule.probability << "\n";
      lsystem.rules.push_back(std::move(rule));
    } else if (t.is_word("interpret")) {
      raw_next();
      const Token where = peek();
      const std::string from = parse_string();
      accept(",");
      const std::string to = parse_string();
      if (from.size() != 1 || to.size() != 1) fail(where.where, "interpret takes two one-character strings");
      turtle.aliases.emplace_back(from[0], to[0]);
      key << "interpret " << from << to << "\n";
    } else if (t.is_word("angle")) {
      raw_next();
      turtle.angle_degrees = parse_float();
    } else if (t.is_word("angle_divisions")) {
      // Fractint's `angle N`: N equal turns make a full circle.
      raw_next();
      turtle.angle_degrees = 360.0 / parse_int("angle_divisions", 1, 1000000);
    } else if (t.is_word("iterations")) {
      raw_next();
      lsystem.iterations = parse_int("iterations", 0, 1000);
    } else if (t.is_word("seed")) {
      raw_next();
      lsystem.seed = static_cast<std::uint64_t>(parse_int("seed", 0));
    } else if (t.is_word("step")) {
      raw_next();
      turtle.step = parse_float();
    } else if (t.is_word("width")) {
      raw_next();
      turtle.width = parse_float();
      if (!(turtle.width >= 0)) fail(t.where, "width must not be negative");
    } else if (t.is_word("taper")) {
      raw_next();
      turtle.taper = parse_float();
      if (!(turtle.taper >= 0)) fail(t.where, "taper must not be negative");
    } else if (t.is_word("max_length")) {
      raw_next();
      lsystem.max_length = static_cast<std::size_t>(parse_int("max_length", 1, 200'000'000));
    } else if (t.is_word("palette")) {
      raw_next();
      expect("{", "palette");
      while (peek().is_word("texture")) {
        raw_next();
        palette.push_back(parse_texture_block());
      }
      expect("}", "palette");
    } else if (t.is_word("leaf")) {
      raw_next();
      expect("{", "leaf");
      leaf = parse_object_if_any();
      if (!leaf) fail(peek().where, "leaf { } holds an object");
      parse_object_modifiers(*leaf);  // modifiers after the object apply to it; reads the closing '}'
    } else if (!parse_object_modifier(o)) {
      break;
    }
  }
  key << "axiom\x1f" << lsystem.axiom << "\nangle " << turtle.angle_degrees << " iterations "
      << lsystem.iterations << " seed " << lsystem.seed << " step " << turtle.step << " width "
      << turtle.width << " taper " << turtle.taper << " max " << lsystem.max_length;

  std::shared_ptr<const GeneratedPlant> plant;
  try {
    plant = cached_plant(key.str(), [&] { return grow(lsystem, turtle); });
  } catch (const std::exception& e) {
    fail(keyword.where, std::string("lsystem: ") + e.what());
  }
  // The union's children: a branch set per colour (textured from the palette) and the leaves. Shapes use
  // the aliasing constructor so they keep the whole plant alive, which keeps the cache entry alive.
  std::vector<ParsedObject> children;
  for (std::size_t c = 0; c < plant->branches.size(); ++c) {
    if (!plant->branches[c]) continue;
    ParsedObject part;
    part.where = keyword.where;
    part.shape = std::shared_ptr<const geometry::Shape>(plant, plant->branches[c].get());
    if (!palette.empty()) part.texture = palette[std::min(c, palette.size() - 1)];
    children.push_back(std::move(part));
  }
  if (leaf) {
    long long nodes = 1;
    for (const procedural::TurtleFrame& f : plant->leaves) {
      ParsedObject placed = *leaf;
      placed.apply(leaf_placement(f));
      count_objects(nodes, placed, keyword.where);
      children.push_back(std::move(placed));
    }
  }
  if (children.empty()) fail(keyword.where, "lsystem: the L-system draws nothing");
  // The children are in the union's own space: its transforms (read with the settings) apply after them.
  o.children = std::move(children);
  return o;
}

}  // namespace snell::sdl
