#pragma once
// Whether anything in this process reads surface (u, v) coordinates: uv_mapping pigments and normals and the
// explain command's uv layer say so when they are made. Until then shapes whose uv costs transcendental
// functions (the atan2 of spheres, cylinders, cones and tori; the sphere's atan2 and asin were 13% of
// POV-Ray's interior/crystal.pov, whose textures never look at uv) leave it zero. A latch: once set it stays
// set, so a scene that reads uv is never shown stale values, and images do not depend on it (a scene that
// reads no uv cannot tell the difference).
#include <atomic>

namespace snell::geometry {

namespace detail {
inline std::atomic<bool> surface_uv_wanted{false};
}

/// Called by every reader of surface uv before rendering starts.
inline void request_surface_uv() {
  detail::surface_uv_wanted.store(true, std::memory_order_relaxed);
}

inline bool surface_uv_requested() {
  return detail::surface_uv_wanted.load(std::memory_order_relaxed);
}

}  // namespace snell::geometry
