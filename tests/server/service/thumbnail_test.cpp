// server/service/png_format and server/service/thumbnail: PNG bytes any reader decodes (zlib and
// CRC-32 checked here), and thumbnails that draw lower(α) opaque and upper(α) translucent around it.
#include "server/service/thumbnail.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>

#include "geometry/voxel/envelope_grid.h"
#include "geometry/voxel/smooth_mesh.h"
#include "server/service/png_format.h"
#include "tests/geometry/fuzzy_ball.h"

namespace fsdb {
namespace {

uint32_t bigEndian(const std::string& s, size_t at) {
  return (uint32_t(uint8_t(s[at])) << 24) | (uint32_t(uint8_t(s[at + 1])) << 16) | (uint32_t(uint8_t(s[at + 2])) << 8) |
         uint32_t(uint8_t(s[at + 3]));
}

// Decodes what toPng writes (checking every chunk's CRC): width, height and RGBA pixels.
RgbaImage decodePng(const std::string& png) {
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  RgbaImage out;
  std::string idat;
  for (size_t at = 8; at < png.size();) {
    const uint32_t length = bigEndian(png, at);
    const std::string type = png.substr(at + 4, 4), data = png.substr(at + 8, length);
    const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(png.data() + at + 4), 4 + length);
    EXPECT_EQ(bigEndian(png, at + 8 + length), uint32_t(crc)) << type;
    if (type == "IHDR") {
      out.width = int(bigEndian(data, 0));
      out.height = int(bigEndian(data, 4));
      EXPECT_EQ(data.substr(8), std::string("\x08\x06\x00\x00\x00", 5));
    } else if (type == "IDAT") {
      idat += data;
    }
    at += 12 + length;
  }
  std::string raw(size_t(out.width) * out.height * 4 + size_t(out.height), '\0');
  uLongf size = raw.size();
  EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(raw.data()), &size, reinterpret_cast<const Bytef*>(idat.data()), idat.size()),
            Z_OK);
  for (int y = 0; y < out.height; ++y) {
    const size_t row = size_t(y) * (size_t(out.width) * 4 + 1);
    EXPECT_EQ(raw[row], '\0');
    out.pixels.insert(out.pixels.end(), raw.begin() + long(row + 1), raw.begin() + long(row + 1 + size_t(out.width) * 4));
  }
  return out;
}

TEST(PngFormat, RoundTripsRgbaPixels) {
  RgbaImage image;
  image.width = 3;
  image.height = 2;
  for (int i = 0; i < 24; ++i) image.pixels.push_back(uint8_t(i * 10));
  const RgbaImage back = decodePng(toPng(image));
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.pixels, image.pixels);
  image.pixels.pop_back();
  EXPECT_THROW(toPng(image), std::invalid_argument);
}

const uint8_t* pixel(const RgbaImage& im, int x, int y) { return &im.pixels[(size_t(y) * im.width + size_t(x)) * 4]; }

TEST(Thumbnail, LowerOpaqueUpperTranslucentAroundIt) {
  const FuzzyBall ball({0, 0, 0}, 0.5, 0.75, 1.0);
  const EnvelopeGrid grid = EnvelopeGrid::build(ball, 0.05);
  const TriangleMesh lower = extractSmoothMesh(grid, ball, 0.5, EnvelopeBound::kLower);
  const TriangleMesh upper = extractSmoothMesh(grid, ball, 0.5, EnvelopeBound::kUpper);
  const RgbaImage im = renderThumbnail(lower, upper, 64);
  ASSERT_EQ(im.width, 64);
  ASSERT_EQ(im.pixels.size(), 64u * 64u * 4u);
  // The centre: the lower ball (radius 0.625) under the upper one (0.875): opaque, blue over orange.
  const uint8_t* c = pixel(im, 32, 32);
  EXPECT_EQ(c[3], 255);
  EXPECT_GT(c[2], c[0]);
  // Between the two radii (0.875 fills 84% of the width, so 0.75 lies at 36% from the centre):
  // upper alone, translucent orange.
  const uint8_t* ring = pixel(im, 32 + int(0.5 * 64 * 0.84 * 0.75 / 0.875) + 1, 32);
  EXPECT_GT(ring[3], 60);
  EXPECT_LT(ring[3], 160);
  EXPECT_GT(ring[0], ring[2]);
  // The corners: nothing.
  EXPECT_EQ(pixel(im, 0, 0)[3], 0);
  EXPECT_EQ(pixel(im, 63, 63)[3], 0);
  // Nothing to draw: all transparent; sizes out of range refused.
  const RgbaImage none = renderThumbnail(TriangleMesh{}, TriangleMesh{}, 16);
  for (size_t i = 3; i < none.pixels.size(); i += 4) EXPECT_EQ(none.pixels[i], 0);
  EXPECT_THROW(renderThumbnail(lower, upper, 8), std::invalid_argument);
  // The same meshes, the same bytes.
  EXPECT_EQ(toPng(renderThumbnail(lower, upper, 64)), toPng(im));
}

}  // namespace
}  // namespace fsdb
