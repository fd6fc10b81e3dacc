// `mesh_camera { rays_per_pixel distribution_type [max_distance] mesh {...}... [smooth] }` inside a camera
// (POV-Ray 3.7 reference "Mesh Camera"; the checks are those of POV-Ray's Parse_Mesh_Camera).
#include "snell/geometry/mesh.hpp"
#include "snell/scene/mesh_camera.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

void Parser::parse_mesh_camera(scene::CameraSpec& cam, const Token& keyword) {
  expect("{", "mesh_camera");
  auto spec = std::make_shared<scene::MeshCameraSpec>();
  // More rays than this would only make a pixel slow; distribution 0 is bounded by its meshes anyway.
  constexpr int kMaxRaysPerPixel = 4096;
  spec->rays_per_pixel = parse_int("mesh_camera rays per pixel", 1, kMaxRaysPerPixel);
  const scene::SourceLocation distribution_at = peek().where;
  spec->distribution = parse_int("mesh_camera distribution type", 0, 3);
  if (spec->distribution >= 2 && spec->rays_per_pixel != 1)
    fail(distribution_at, "mesh_camera distribution types 2 and 3 take 1 ray per pixel");
  if (starts_numeric()) spec->max_distance = parse_float();
  for (;;) {
    const Token t = peek();
    if (!t.is_word("mesh") && !t.is_word("mesh2")) break;
    raw_next();
    const ParsedObject o = parse_object(t);
    auto mesh = std::dynamic_pointer_cast<const geometry::Mesh>(o.shape);
    if (!mesh) fail(t.where, "mesh_camera needs a mesh or mesh2");
    spec->meshes.push_back({std::move(mesh), o.transform});
  }
  const Token smooth = peek();
  if (smooth.is_word("smooth")) {
    raw_next();
    if (spec->distribution != 3) fail(smooth.where, "mesh_camera smooth needs distribution type 3");
    spec->smooth = true;
  }
  if (spec->meshes.empty()) fail(peek().where, "mesh_camera needs at least one mesh or mesh2");
  expect("}", "mesh_camera");
  if (spec->distribution == 0 && spec->rays_per_pixel > static_cast<int>(spec->meshes.size()))
    fail(keyword.where, "mesh_camera distribution type 0 needs a mesh for each ray per pixel");
  if (spec->distribution == 3 && spec->meshes.size() > 1)
    warn(keyword.where, "mesh_camera distribution type 3 uses only the first mesh");
  cam.kind = scene::CameraSpec::Kind::mesh;
  cam.mesh = std::move(spec);
}

}  // namespace snell::sdl
