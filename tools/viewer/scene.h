// Milestone 5's scenes in the viewer (keys 7 to 9), as plain data that either flavour draws
// with its own m5::draw_scene (flavour_api.h):
//
//   textured  the model with a generated brick texture, trilinear filtering, Lambert and
//             ambient light;
//   specular  the model in its plain color with Blinn-Phong highlights;
//   shadowed  the model (plain color, some specular) over a checkerboard floor that receives
//             its shadow: one shadow map from the directional light, 3x3 PCF.
//
// Texture coordinates. Meshes here carry none (OBJ files' are not loaded), so the viewer makes
// them: the generated tori by their own angles (u around the ring, v around the tube), every
// other model by a spherical mapping (u the angle around the y axis, v from the top pole down).
// Both angles wrap, so a triangle that crosses the seam would interpolate backwards across the
// whole texture: its corners on the far side get u + 1 (or v + 1), and a position whose
// triangles need both gets two vertices (same position and normal, two uvs). With the repeat
// wrap mode, u and u + 1 show the same texel, so the seam does not show. A pole (a position on
// the y axis) has no angle: each of its triangles gives it the mean u of its other corners.
#pragma once

#include "flavour_api.h"
#include "model.h"

namespace viewer {

// Texture repeats over the model: the texture spans 1 / repeats_u of the way around.
struct UvRepeats {
    int u = 8, v = 4;
};
UvRepeats uv_repeats(UvMapping mapping);

// The mesh with one uv per position after splitting at the seams (see above), uv scaled by
// `repeats`. Normals: the mesh's own, else area-weighted vertex normals (milestone 4's rule),
// computed before splitting so that the two sides of a seam share them.
TexturedMesh with_uvs(const raster::Mesh& mesh, UvMapping mapping, double ring_radius, UvRepeats repeats);

// The generated textures: bricks (128 x 128 texels, four courses of two bricks, the odd
// courses offset by half a brick) and a checkerboard (64 x 64, 2 x 2 squares).
raster::Image brick_texture();
raster::Image checker_texture();

// The floor's half side (world units): a square of 2 kFloorHalfSide per side under the model.
inline constexpr double kFloorHalfSide = 2.0;

// Everything the scene modes draw for `model` (the model fits the unit sphere: model.h).
SceneAssets make_scene_assets(const Model& model);

// What scene mode `mode` draws; a mode that is not one gives the plain model, unlit features off.
SceneSetup scene_setup(Mode mode, const SceneAssets& assets);

}  // namespace viewer
