#pragma once
// The SVG file format of exported curves (GET /curves/{id}/svg): polylines in curve coordinates
// and optional dots (the given points of a fair curve), in one picture whose viewBox holds them
// all with a 5% margin. y grows upwards in the curve and downwards in SVG: a group flips it.
// Each polyline is <polyline id="..." stroke="..." points="x,y x,y ..."/> (numbers as
// geometry/core/number_format.h writes them), with stroke-width="..." after points when `width` is
// not 1 (a multiple of the picture's base width); later polylines are drawn on top.
#include <array>
#include <string>
#include <vector>

namespace fsdb {

struct SvgPolyline {
  std::string id;
  std::string colour;  // "#rrggbb"
  std::vector<std::array<double, 2>> points;
  double width = 1.0;
};

std::string toSvg(const std::string& title, const std::vector<SvgPolyline>& lines,
                  const std::vector<std::array<double, 2>>& dots = {});

}  // namespace fsdb
