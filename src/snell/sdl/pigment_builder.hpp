#pragma once
// What a pigment (or normal) block has said so far about its pattern: shared by pigments.cpp and
// normals.cpp. Only the parser includes this.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "snell/sdl/parser.hpp"
#include "snell/texture/average_pigment.hpp"
#include "snell/texture/cellular_patterns.hpp"
#include "snell/texture/density_file.hpp"
#include "snell/texture/fractal_patterns.hpp"
#include "snell/texture/noise_patterns.hpp"
#include "snell/texture/pattern_pigment.hpp"
#include "snell/texture/ripple_patterns.hpp"
#include "snell/texture/spiral_patterns.hpp"
#include "snell/texture/value_patterns.hpp"

namespace snell::sdl {

using texture::PigmentPtr;

/// What a pigment block has said so far. With no pattern it is just `plain` (a colour or a declared
/// pigment); with one it is a texture::PatternSpec in the making.
struct Parser::PigmentBuilder {
  PigmentPtr plain;
  bool patterned = false;
  texture::PatternSpec spec;  // warps without the classic turbulence, which is kept apart:
  std::optional<texture::TurbulenceParams> turbulence;
  std::vector<texture::PigmentMap::Entry> pigment_entries;
  /// Patterns built in build_spec() from parameters that may follow them: marble, wood and agate (which
  /// use the turbulence themselves), ripples and waves (which take frequency and phase themselves),
  /// crackle, quilted, spiral1 and spiral2.
  std::string special;
  double agate_turb = 1.0;
  texture::CrackleParams crackle;
  double control0 = 1, control1 = 1;
  double arms = 1;
  /// `uv_mapping`: kept through start_pattern (it may come before the pattern).
  bool uv_mapping = false;
  texture::FractalShading fractal;
  texture::MagnetParams magnet;
  double julia_real = 0, julia_imaginary = 0;
  bool brick = false;
  math::Vec3 brick_size{8, 3, 4.5};
  double mortar = 0.5;
  /// `density_file df3 "file" [interpolate n]` (density_file.hpp).
  std::shared_ptr<const texture::DensityGrid> density_grid;
  int density_interpolation = 0;
  /// `noise_generator`: the pattern's own, or the parser's global_settings cell (povray_noise.hpp).
  texture::NoiseChoice noise;

  /// Starts from an existing pigment: a patterned one can be modified further.
  void start_from(const PigmentPtr& pigment) {
    const bool uv = uv_mapping;
    *this = PigmentBuilder{};
    uv_mapping = uv;
    const auto* pattern = dynamic_cast<const texture::PatternPigment*>(pigment.get());
    if (!pattern) {
      plain = pigment;
      return;
    }
    patterned = true;
    spec = pattern->spec();
    texture::WarpList rest;
    for (const auto& w : spec.warps.warps()) {
      const auto* t = dynamic_cast<const texture::TurbulenceWarp*>(w.get());
      if (t && !turbulence && rest.empty())
        turbulence = t->params();
      else
        rest.push(w);
    }
    spec.warps = rest;
    if (spec.pigment_map) pigment_entries = spec.pigment_map->entries();
    spec.pigment_map.reset();
    brick = dynamic_cast<const texture::BrickPattern*>(spec.block_pattern.get()) != nullptr;
  }

  /// A pattern keyword replaces whatever colour or pattern came before it in the block.
  void start_pattern() {
    const bool uv = uv_mapping;
    *this = PigmentBuilder{};
    patterned = true;
    uv_mapping = uv;
  }

  texture::TurbulenceParams& turbulence_params() {
    if (!turbulence) turbulence = texture::TurbulenceParams{};
    return *turbulence;
  }

  void transform(const math::Transform& t) {
    if (!patterned) {
      plain = texture::transform_pigment(plain, t);
      return;
    }
    // The map's or blocks' pigments move with the pattern through the point: they are evaluated where this
    // pigment's warps, transforms included, take it (POV-Ray's Transform_Tpattern adds to the pattern's
    // own warps only; Compute_Pigment evaluates an entry at the warped point).
    spec.warps.push(std::make_shared<texture::TransformWarp>(t));
  }

  /// The pattern, wave and warps as written (for a pigment or a normal).
  texture::PatternSpec build_spec() const {
    texture::PatternSpec out = spec;
    if (brick) out.block_pattern = std::make_shared<texture::BrickPattern>(brick_size, mortar);
    if (special == "density_file")
      out.value_pattern = std::make_shared<texture::DensityFilePattern>(density_grid, density_interpolation);
    if (special == "bozo") out.value_pattern = std::make_shared<texture::BozoPattern>(noise);
    if (special == "granite") out.value_pattern = std::make_shared<texture::GranitePattern>(noise);
    if (special == "wrinkles") out.value_pattern = std::make_shared<texture::WrinklesPattern>(noise);
    if (special == "bumps") out.value_pattern = std::make_shared<texture::BumpsPattern>(noise);
    if (special == "dents") out.value_pattern = std::make_shared<texture::DentsPattern>(noise);
    if (special == "marble") out.value_pattern = std::make_shared<texture::MarblePattern>(turbulence, noise);
    if (special == "wood") out.value_pattern = std::make_shared<texture::WoodPattern>(turbulence);
    if (special == "agate")
      out.value_pattern = std::make_shared<texture::AgatePattern>(
          turbulence.value_or(texture::TurbulenceParams{}), agate_turb, noise);
    if (special == "crackle") {
      texture::CrackleParams params = crackle;
      params.noise = noise;
      out.value_pattern = std::make_shared<texture::CracklePattern>(params);
    }
    if (special == "quilted")
      out.value_pattern = std::make_shared<texture::QuiltedPattern>(control0, control1);
    if (special == "mandel") out.value_pattern = std::make_shared<texture::MandelPattern>(fractal);
    if (special == "julia")
      out.value_pattern = std::make_shared<texture::JuliaPattern>(julia_real, julia_imaginary, fractal);
    if (special == "magnet") out.value_pattern = std::make_shared<texture::MagnetPattern>(magnet, fractal);
    if (special == "spiral1") out.value_pattern = std::make_shared<texture::Spiral1Pattern>(arms);
    if (special == "spiral2") out.value_pattern = std::make_shared<texture::Spiral2Pattern>(arms);
    if (special == "ripples" || special == "waves") {
      // POV-Ray gives these two frequency and phase as their own parameters, not the wave's.
      const double f = spec.wave.frequency, ph = spec.wave.phase;
      if (special == "ripples") out.value_pattern = std::make_shared<texture::RipplesPattern>(f, ph);
      if (special == "waves") out.value_pattern = std::make_shared<texture::WavesPattern>(f, ph);
      out.wave.frequency = 1;
      out.wave.phase = 0;
    }
    const bool own_turbulence = special == "marble" || special == "wood" || special == "agate";
    if (turbulence && !own_turbulence) {
      texture::WarpList warps;
      warps.push(std::make_shared<texture::TurbulenceWarp>(*turbulence));
      for (const auto& w : spec.warps.warps()) warps.push(w);
      out.warps = warps;
    }
    if (!pigment_entries.empty()) out.pigment_map.emplace(pigment_entries);
    return out;
  }

  PigmentPtr build() const {
    // `average` is no lookup: the weighted mean of its pigment_map's entries (average_pigment.hpp).
    PigmentPtr pigment = special == "average" ? std::make_shared<texture::AveragePigment>(pigment_entries)
                         : patterned          ? std::make_shared<texture::PatternPigment>(build_spec())
                                              : plain;
    if (uv_mapping && pigment) pigment = std::make_shared<texture::UvMappedPigment>(pigment);
    return pigment;
  }
};

/// A texture block's pattern part: `gradient x texture_map {..}` or `checker texture {A} texture {B}`.
struct Parser::TexturePatternBuilder {
  bool active = false;
  PigmentBuilder pattern;
  std::vector<std::pair<double, std::shared_ptr<const material::Texture>>> map;
  std::vector<std::shared_ptr<const material::Texture>> blocks;
  /// `material_map {}`: the whole selector, read at once.
  std::shared_ptr<const material::TextureSelector> material_map;
};

}  // namespace snell::sdl
