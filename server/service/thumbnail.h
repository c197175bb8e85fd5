#pragma once
// Thumbnails of fuzzy shapes: a small shaded picture of lower(α) solid and upper(α) translucent
// around it, drawn by a software rasteriser (no display, no GPU, no library: a z-buffer over the
// triangles, enough for a few thousand of them at 128 pixels, and the same bytes on every machine).
//
// Picture: orthographic, seen from the front right and above (view direction towards −(1, 0.9,
// 1.6) in the X right, Y up, Z front frame of the vocabulary), the upper mesh's extent fitted
// with an 8% margin; Lambert shading from a light above the viewer's left shoulder plus ambient,
// both sides of a triangle lit alike. lower(α) is opaque blue; upper(α) orange over it (35%
// over lower, 45% alone over the transparent background). Rendered at twice the size and
// averaged down 2 x 2 (anti-aliasing).
#include "geometry/voxel/envelope_mesh.h"
#include "server/service/png_format.h"

namespace fsdb {

// A `size` x `size` RGBA image (transparent where nothing is drawn). size in [16, 1024], else
// std::invalid_argument. Empty meshes draw nothing (an empty lower at high α is only upper).
RgbaImage renderThumbnail(const TriangleMesh& lower, const TriangleMesh& upper, int size);

}  // namespace fsdb
