#pragma once
// PNG files (ISO/IEC 15948): 8-bit RGBA, one IDAT of zlib-deflated rows (filter type 0),
// CRC-32 per chunk. Enough for thumbnails; browsers and every image tool read it.
#include <cstdint>
#include <string>
#include <vector>

namespace fsdb {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // row-major, top row first, 4 bytes a pixel (r, g, b, a)
};

// Throws std::invalid_argument when pixels.size() != width·height·4 or a side is not positive.
std::string toPng(const RgbaImage& image);

}  // namespace fsdb
