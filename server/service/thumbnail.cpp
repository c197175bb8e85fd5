// See server/service/thumbnail.h.
#include "server/service/thumbnail.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace fsdb {
namespace {

struct View {
  Vec3 toViewer, right, up;
  double scale = 1, cx = 0, cy = 0;  // world → pixels: x = (p·right − cx)·scale + size/2
  int size = 0;
  double px(const Vec3& p) const { return (dot(p, right) - cx) * scale + size / 2.0; }
  double py(const Vec3& p) const { return size / 2.0 - (dot(p, up) - cy) * scale; }
};

// One layer: the nearest surface's depth (larger: nearer) and brightness per pixel.
struct Layer {
  std::vector<double> depth;
  std::vector<float> light;
  explicit Layer(int size)
      : depth(size_t(size) * size, -std::numeric_limits<double>::infinity()), light(size_t(size) * size, 0) {}
  bool drawn(size_t i) const { return depth[i] != -std::numeric_limits<double>::infinity(); }
};

void rasterise(const TriangleMesh& mesh, const View& v, const Vec3& light, Layer& layer) {
  const int n = v.size;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    Vec3 normal = cross(b - a, c - a);
    const double len = norm(normal);
    if (len == 0) continue;
    normal = normal / len;
    const float shade = float(0.3 + 0.7 * std::fabs(dot(normal, light)));
    const double ax = v.px(a), ay = v.py(a), bx = v.px(b), by = v.py(b), cx = v.px(c), cy = v.py(c);
    const double da = dot(a, v.toViewer), db = dot(b, v.toViewer), dc = dot(c, v.toViewer);
    const double area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (area == 0) continue;
    const int x0 = std::max(0, int(std::floor(std::min({ax, bx, cx})))),
              x1 = std::min(n - 1, int(std::ceil(std::max({ax, bx, cx}))));
    const int y0 = std::max(0, int(std::floor(std::min({ay, by, cy})))),
              y1 = std::min(n - 1, int(std::ceil(std::max({ay, by, cy}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double sx = x + 0.5, sy = y + 0.5;  // pixel centre
        const double w0 = ((bx - sx) * (cy - sy) - (by - sy) * (cx - sx)) / area;
        const double w1 = ((cx - sx) * (ay - sy) - (cy - sy) * (ax - sx)) / area;
        const double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double d = w0 * da + w1 * db + w2 * dc;
        const size_t i = size_t(y) * size_t(n) + size_t(x);
        if (d > layer.depth[i]) {
          layer.depth[i] = d;
          layer.light[i] = shade;
        }
      }
    }
  }
}

}  // namespace

RgbaImage renderThumbnail(const TriangleMesh& lower, const TriangleMesh& upper, int size) {
  if (size < 16 || size > 1024) throw std::invalid_argument("renderThumbnail: size lies in [16, 1024]");
  const int n = 2 * size;  // drawn at twice the size, averaged down
  View v;
  v.size = n;
  v.toViewer = Vec3{1, 0.9, 1.6} / norm(Vec3{1, 0.9, 1.6});
  v.right = cross(Vec3{0, 1, 0}, v.toViewer);
  v.right = v.right / norm(v.right);
  v.up = cross(v.toViewer, v.right);
  // Fit the upper mesh (it holds the lower) or, if empty, the lower one.
  const TriangleMesh& extent = upper.vertices.empty() ? lower : upper;
  double lox = std::numeric_limits<double>::infinity(), hix = -lox, loy = lox, hiy = -lox;
  for (const Vec3& p : extent.vertices) {
    lox = std::min(lox, dot(p, v.right));
    hix = std::max(hix, dot(p, v.right));
    loy = std::min(loy, dot(p, v.up));
    hiy = std::max(hiy, dot(p, v.up));
  }
  if (!extent.vertices.empty()) {
    v.cx = (lox + hix) / 2;
    v.cy = (loy + hiy) / 2;
    const double span = std::max({hix - lox, hiy - loy, 1e-12});
    v.scale = n * (1 - 2 * 0.08) / span;
  }
  const Vec3 light = Vec3{-0.3, 1.0, 0.6} / norm(Vec3{-0.3, 1.0, 0.6});
  Layer low(n), up(n);
  rasterise(lower, v, light, low);
  rasterise(upper, v, light, up);
  // Composite at full size, then average 2 x 2 (premultiplied, so edges blend with transparency).
  const std::array<float, 3> blue{70, 115, 205}, orange{235, 130, 50};
  std::vector<std::array<float, 4>> big(size_t(n) * n, {0, 0, 0, 0});
  for (size_t i = 0; i < big.size(); ++i) {
    std::array<float, 4> c{0, 0, 0, 0};
    if (low.drawn(i)) c = {blue[0] * low.light[i], blue[1] * low.light[i], blue[2] * low.light[i], 1};
    if (up.drawn(i) && (!low.drawn(i) || up.depth[i] >= low.depth[i])) {
      const float a = low.drawn(i) ? 0.35f : 0.45f;
      for (int k = 0; k < 3; ++k) c[k] = c[k] * (1 - a) + orange[k] * up.light[i] * a;
      c[3] = c[3] * (1 - a) + a;
    }
    big[i] = c;
  }
  RgbaImage image;
  image.width = image.height = size;
  image.pixels.resize(size_t(size) * size * 4);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      std::array<float, 4> sum{0, 0, 0, 0};
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          for (int k = 0; k < 4; ++k) sum[k] += big[size_t(2 * y + dy) * n + size_t(2 * x + dx)][k] / 4;
      const size_t o = (size_t(y) * size + size_t(x)) * 4;
      // Colours are premultiplied by coverage: divide back where anything was drawn.
      for (int k = 0; k < 3; ++k)
        image.pixels[o + k] = std::uint8_t(std::clamp(sum[3] > 0 ? sum[k] / sum[3] : 0.0f, 0.0f, 255.0f) + 0.5f);
      image.pixels[o + 3] = std::uint8_t(std::clamp(sum[3] * 255.0f, 0.0f, 255.0f) + 0.5f);
    }
  }
  return image;
}

}  // namespace fsdb
