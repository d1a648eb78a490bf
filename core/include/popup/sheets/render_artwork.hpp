#pragma once
#include <vector>

#include "popup/input/model_mesh.hpp"
#include "popup/input/texture_image.hpp"
#include "popup/model/patch.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// How a model's appearance is rendered onto a patch (docs/DESIGN.md, "Artwork"). Lengths in mm
/// of the card frame (the model already placed on the card).
struct ArtworkOptions {
    double pixels_per_mm = 300.0 / 25.4; ///< 300 dpi; in (0, 40]
    /// How far in front of the patch, on the rendered side, a model surface still counts: what
    /// lies farther belongs to other patches. > 0, may be infinite.
    double depth = 10.0;
    /// How far behind the patch a model surface still counts (the patch stands a little in front
    /// of the surface it approximates); >= 0 and finite.
    double behind = 1.0;
    /// Render the side the patch's normal points away from (printed when the piece shows that
    /// side up on its sheet, FlatPatch::normal_side_up() false).
    bool back_side = false;
    Vec3 light = Vec3(1.0, -1.0, 2.0); ///< towards the light (card frame), for plain models
    double ambient = 0.3;              ///< share of light everywhere, [0, 1]
    long long max_pixels = 25'000'000; ///< largest image (width × height), [1, 1e8]
};

/// The model seen orthographically along a patch's normal, as an image laid on the patch's own
/// 2D frame (Patch::to_local: origin, u, v from derive_frame). Column c, row r of the image
/// covers u in origin.x + [c, c + 1] * mm_per_pixel and v in origin.y + [h - 1 - r, h - r] *
/// mm_per_pixel (row 0 at the top, v up). Pixels where no surface counts are transparent.
struct PatchArtwork {
    int patch = 0;              ///< the patch's id
    RgbaImage image;            ///< covers the patch's bounding box in its frame
    Vec2 origin = Vec2::Zero(); ///< (u, v) of the image's lower-left corner
    double mm_per_pixel = 0.0;
    bool back_side = false;           ///< rendered from the side opposite the normal
    Vec3 frame_origin = Vec3::Zero(); ///< the patch frame the image is laid on (design state)
    Vec3 frame_u = Vec3::UnitX();
    Vec3 frame_v = Vec3::UnitY();
    Vec3 frame_normal = Vec3::UnitZ();
    long long covered_pixels = 0; ///< pixels showing a model surface
};

/// Renders `mesh` (card mm) onto `patch` (design state) with a z-buffer: for each pixel centre
/// of the patch's bounding box, the first front-facing triangle met looking along the patch's
/// normal (towards it, from the rendered side) within [-behind, depth] of its plane gives the
/// colour: the texture (read_model_texture: embedded or a file; bilinear, repeating; v = 0 is
/// the image's bottom row), else the interpolated vertex colours, else base_colour × (ambient +
/// (1 − ambient) × max(0, n · light)) with the triangle's normal n. A texture that cannot be
/// read (or mapped: no texture coordinates) gives an unreadable_texture warning naming the model
/// and the texture, and the next of these. Bad options, a bad mesh or a degenerate patch fail with
/// a diagnostic naming the value and the allowed range.
Result<PatchArtwork> render_artwork(const ModelMesh& mesh, const Patch& patch,
                                    const ArtworkOptions& options = {});

/// render_artwork for several patches of one model, reading its texture once.
Result<std::vector<PatchArtwork>> render_artworks(const ModelMesh& mesh,
                                                  const std::vector<Patch>& patches,
                                                  const ArtworkOptions& options = {});

/// Checks the options alone; errors name the option, its value and the allowed range.
Diagnostics check_artwork_options(const ArtworkOptions& options);

} // namespace popup
