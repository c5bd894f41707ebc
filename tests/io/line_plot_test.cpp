// Load-displacement plots: tick values worked out by hand, and files a viewer can open (a PNG
// signature and dimensions, an SVG root element).
#include <fstream>

#include <gtest/gtest.h>

#include <bimrock/io/line_plot.hpp>

#include "support/run_bimrock.hpp"

namespace bimrock {
namespace {

TEST(LinePlot, NiceTicksAreRoundNumbersCoveringTheRange) {
  EXPECT_EQ(nice_ticks(0.0, 40.0), (std::vector<double>{0, 10, 20, 30, 40}));
  // span 1.2 over 5 gaps: 0.24 per gap; the smallest of 0.1, 0.2, 0.5 not below it is 0.5.
  EXPECT_EQ(nice_ticks(-0.3, 0.9), (std::vector<double>{-0.5, 0, 0.5, 1.0}));
  const auto small = nice_ticks(0.0, 3.7e-5);
  EXPECT_NEAR(small[1] - small[0], 1e-5, 1e-18);
  EXPECT_GE(small.back(), 3.7e-5);
}

TEST(LinePlot, WritesAPngAndAnSvg) {
  const auto dir = testing::fresh_folder("bimrock-plot");
  LinePlot plot{"P at A",
                "horizontal displacement at A [mm]",
                "P [kN]",
                {{"A", {0.0, 0.1, 0.2, 3.0}, {0.0, 20.0, 40.0, 40.0}}}};
  write_line_plot(plot, dir / "curve");
  std::ifstream png(dir / "curve.png", std::ios::binary);
  char header[24] = {};
  png.read(header, 24);
  EXPECT_EQ(std::string(header + 1, 3), "PNG");
  // Width and height, big-endian, at bytes 16..23 of the IHDR chunk.
  const auto be32 = [&](int at) {
    return (unsigned char)header[at] << 24 | (unsigned char)header[at + 1] << 16 |
           (unsigned char)header[at + 2] << 8 | (unsigned char)header[at + 3];
  };
  EXPECT_EQ(be32(16), 640);
  EXPECT_EQ(be32(20), 440);
  EXPECT_NE(testing::read_text(dir / "curve.svg").find("<svg"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace bimrock
