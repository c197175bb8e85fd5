// server/service/svg_format: the exact SVG of a small picture (viewBox with its margin, flipped y,
// polylines in order with their widths, dots).
#include "server/service/svg_format.h"

#include <gtest/gtest.h>

namespace fsdb {
namespace {

TEST(SvgFormat, WritesPolylinesAndDotsInsideAMarginedViewBox) {
  // Points span x in [0, 10], y in [0, 5]: margin 0.5, base width 0.1.
  const std::string svg = toSvg("two lines", {{"a", "#ff0000", {{0, 0}, {10, 5}}}, {"b", "#000000", {{0, 5}, {10, 0}}, 2.0}},
                                {{5, 2.5}});
  EXPECT_EQ(svg,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-0.5 -5.5 11 6\">\n"
            "<title>two lines</title>\n"
            "<g transform=\"scale(1,-1)\" fill=\"none\" stroke-width=\"0.1\">\n"
            "<polyline id=\"a\" stroke=\"#ff0000\" points=\"0,0 10,5\"/>\n"
            "<polyline id=\"b\" stroke=\"#000000\" points=\"0,5 10,0\" stroke-width=\"0.2\"/>\n"
            "<circle class=\"point\" cx=\"5\" cy=\"2.5\" r=\"0.3\" fill=\"#000000\" stroke=\"none\"/>\n"
            "</g>\n</svg>\n");
}

TEST(SvgFormat, AnEmptyPictureIsStillValid) {
  const std::string svg = toSvg("nothing", {});
  EXPECT_NE(svg.find("viewBox=\"-0.05 -1.05 1.1 1.1\""), std::string::npos) << svg;
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

}  // namespace
}  // namespace fsdb
