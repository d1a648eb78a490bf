#pragma once
#include <array>
#include <vector>

#include "popup/geometry/vectors.hpp"
#include "popup/input/texture_image.hpp"
#include "popup/model/result.hpp"

namespace popup {

/// A triangle mesh drawn in one colour (RGB in [0, 1]), flat-shaded per triangle.
struct ViewMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    Vec3 colour = Vec3(0.55, 0.65, 0.85);
};

/// A planar polygon (its first loop the outline, the others holes: even-odd filled) drawn in one
/// colour, flat-shaded, its loops outlined.
struct ViewPolygon {
    std::vector<std::vector<Vec3>> loops;
    Vec3 colour = Vec3(0.95, 0.88, 0.70);
    bool outlined = true;
};

/// An orthographic camera and the look of the picture. The image's centre shows `centre`; +x of
/// the image is up × towards_eye, +y (rows go down) is −up, so `up` points up in the picture.
struct ViewCamera {
    Vec3 towards_eye = Vec3(0, 0, 1); ///< from the scene to the viewer; non-zero
    Vec3 up = Vec3(0, 0, 1);          ///< projected, its part across towards_eye is up
    Vec3 centre = Vec3::Zero();
    double mm_per_pixel = 1.0;          ///< > 0
    int width = 800;                    ///< pixels, [1, 8192]
    int height = 800;                   ///< pixels, [1, 8192]
    Vec3 light = Vec3(0.6, -0.3, 0.75); ///< towards the light; both faces of a surface are lit
    double ambient = 0.45;              ///< share of light everywhere, [0, 1]
    Vec3 background = Vec3(1, 1, 1);
    Vec3 edge_colour = Vec3(0.2, 0.2, 0.2);
    double edge_px = 1.0; ///< outline width in pixels, [0, 16]
    int supersample = 1;  ///< drawn this many times wider and higher, then averaged; [1, 4]
};

/// The meshes and polygons seen by `camera` with a z-buffer: each pixel centre shows the surface
/// nearest the eye, coloured colour × (ambient + (1 − ambient) × |n · light|) with the surface's
/// normal n, or the background (alpha 0 there, 255 elsewhere; averaged over the supersamples).
/// Polygon outlines are drawn over the surfaces they lie on and hidden behind nearer ones. Bad
/// camera values, non-finite points or triangle indices out of range fail with a bad_option
/// diagnostic naming the value and its allowed range.
Result<RgbaImage> render_view(const std::vector<ViewMesh>& meshes,
                              const std::vector<ViewPolygon>& polygons, const ViewCamera& camera);

} // namespace popup
