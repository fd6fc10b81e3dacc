#pragma once
// POV-Ray 3.7's photon mapping settings (reference "Photons"; defaults from source/parser/parser.cpp,
// global_settings' photons block): the global `photons {}` block, an object's `photons {}` and a light's.
// snell shoots caustic photons only (render/photons/): light reflected or refracted by target objects and
// stored on the surfaces it reaches next.
#include <memory>

namespace snell::scene {

/// `global_settings { photons { ... } }`.
struct PhotonSettings {
  /// `spacing`: the distance between photons where they reach a target (scaled by the target's multiplier).
  double spacing = 1;
  /// `count`: when above 0, the spacing is chosen so that about this many photons are shot.
  int count = 0;
  /// `gather min, max`: photons per estimate; the search radius grows until `min` are found.
  int gather_min = 20;
  int gather_max = 100;
  /// `jitter`: random offset of each photon within its angular cell, as a fraction of the cell.
  double jitter = 0.4;
  /// `max_trace_level` and `adc_bailout` of photon paths; below 0 the scene's own are used.
  int max_trace_level = -1;
  double adc_bailout = -1;
  /// `autostop`: stop shooting rings at a target once past this fraction of its angle and a ring misses.
  double autostop = 0.5;
  /// `expand_thresholds`: a wider search is kept when the density grows less than `expand_tolerance`
  /// relative, or when it found fewer than `expand_min_count` photons.
  double expand_tolerance = 0.2;
  int expand_min_count = 35;
  /// `radius gather, multiplier, media_gather, media_multiplier`: the first search radius (<= 0: estimated
  /// from the photon density) and a factor on it. The media values are read and not used.
  double gather_radius = -1;
  double gather_radius_multiplier = 1;
  /// `media steps, factor`: media photons; read and not used by snell.
  int media_steps = 0;
  double media_spacing_factor = 1;
};

/// POV-Ray's photon reflection/refraction switches are three-way: not given, on, off (an object and a light
/// both decide; source/core/lighting/photons.cpp).
enum class PhotonSwitch : unsigned char { unset, on, off };

/// What a `target` object holds; every part of one target object shares the same one, so that photons
/// are shot once at the whole object (the bounding sphere of its parts).
struct PhotonTarget {
  /// `target multiplier`: scales the global spacing for this object.
  double spacing_multiplier = 1;
};

/// An object's `photons { target refraction reflection collect pass_through }`.
struct ObjectPhotons {
  std::shared_ptr<const PhotonTarget> target;
  PhotonSwitch refraction = PhotonSwitch::unset;
  PhotonSwitch reflection = PhotonSwitch::unset;
  /// `collect off`: photons are neither stored on it nor gathered at it.
  bool collect = true;
  /// `pass_through`: photons cross it unchanged.
  bool pass_through = false;
};

/// A child's photon settings: its own where given, else its parent's (POV-Ray sets them on the union and
/// its parts answer to them).
inline ObjectPhotons inherit_photons(const ObjectPhotons& own, const ObjectPhotons& parent) {
  ObjectPhotons p = own;
  if (!p.target) p.target = parent.target;
  if (p.refraction == PhotonSwitch::unset) p.refraction = parent.refraction;
  if (p.reflection == PhotonSwitch::unset) p.reflection = parent.reflection;
  p.collect = own.collect && parent.collect;
  p.pass_through = own.pass_through || parent.pass_through;
  return p;
}

/// A light's `photons { refraction reflection area_light }`.
struct LightPhotons {
  PhotonSwitch refraction = PhotonSwitch::unset;
  PhotonSwitch reflection = PhotonSwitch::unset;
  /// `area_light`: photons leave from every point of an area light's grid, not only its centre.
  bool area_light = false;
};

/// Whether an object with switch `object` passes photons of a light with switch `light` on: either says on
/// and the other does not say off (POV-Ray 3.7 photons.cpp, PhotonTrace::ComputeLightedTexture).
inline bool photon_switch_on(PhotonSwitch object, PhotonSwitch light) {
  return (object == PhotonSwitch::on && light != PhotonSwitch::off) ||
         (object != PhotonSwitch::off && light == PhotonSwitch::on);
}

}  // namespace snell::scene
