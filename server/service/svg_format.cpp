#include "server/service/svg_format.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geometry/core/number_format.h"

namespace fsdb {

std::string toSvg(const std::string& title, const std::vector<SvgPolyline>& lines,
                  const std::vector<std::array<double, 2>>& dots) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  auto extend = [&](const std::array<double, 2>& q) {
    x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]), y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
  };
  for (const SvgPolyline& l : lines)
    for (const auto& q : l.points) extend(q);
  for (const auto& q : dots) extend(q);
  if (!(x0 <= x1)) x0 = y0 = 0, x1 = y1 = 1;  // nothing to draw: a unit picture
  const double margin = 0.05 * std::max({x1 - x0, y1 - y0, 1e-9});
  x0 -= margin, y0 -= margin, x1 += margin, y1 += margin;
  const double base = margin / 5;
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << formatNumber(x0) << " " << formatNumber(-y1) << " "
    << formatNumber(x1 - x0) << " " << formatNumber(y1 - y0) << "\">\n"
    << "<title>" << title << "</title>\n"
    << "<g transform=\"scale(1,-1)\" fill=\"none\" stroke-width=\"" << formatNumber(base) << "\">\n";
  for (const SvgPolyline& l : lines) {
    s << "<polyline id=\"" << l.id << "\" stroke=\"" << l.colour << "\" points=\"";
    for (std::size_t i = 0; i < l.points.size(); ++i)
      s << (i ? " " : "") << formatNumber(l.points[i][0]) << "," << formatNumber(l.points[i][1]);
    s << "\"";
    if (l.width != 1.0) s << " stroke-width=\"" << formatNumber(base * l.width) << "\"";
    s << "/>\n";
  }
  for (const auto& q : dots)
    s << "<circle class=\"point\" cx=\"" << formatNumber(q[0]) << "\" cy=\"" << formatNumber(q[1]) << "\" r=\""
      << formatNumber(0.6 * margin) << "\" fill=\"#000000\" stroke=\"none\"/>\n";
  s << "</g>\n</svg>\n";
  return s.str();
}

}  // namespace fsdb
