// Charts drawn with cairo: series land where their data says, bands are tinted, and degenerate
// input never crashes.
#include <gtest/gtest.h>

#include <cairo.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "reports/plot/chart_painter.hpp"
#include "reports/plot/plot_style.hpp"

namespace feedflow {
namespace {

Chart sample_chart() {
  Chart c;
  c.id = "bc";
  c.title = "Critical outlet width against semi-angle";
  c.x = {"semi-angle", "deg"};
  c.y = {"critical outlet width", "mm"};
  c.series.push_back({"band", SeriesStyle::band, {10, 20, 30, 40}, {10, 12, 14, 16}, {30, 34, 38, 42}});
  c.series.push_back({"Jenike", SeriesStyle::line, {10, 20, 30, 40}, {20, 23, 26, 29}, {}});
  c.series.push_back({"design", SeriesStyle::marker, {30}, {60}, {}});
  return c;
}

struct Pixels {
  cairo_surface_t* surface;
  explicit Pixels(const std::string& png_bytes) {
    struct Reader { const std::string* s; std::size_t pos; } r{&png_bytes, 0};
    surface = cairo_image_surface_create_from_png_stream(
        [](void* closure, unsigned char* data, unsigned int length) {
          auto* rd = static_cast<Reader*>(closure);
          if (rd->pos + length > rd->s->size()) return CAIRO_STATUS_READ_ERROR;
          std::copy_n(rd->s->data() + rd->pos, length, data);
          rd->pos += length;
          return CAIRO_STATUS_SUCCESS;
        },
        &r);
  }
  ~Pixels() { cairo_surface_destroy(surface); }
  // r, g, b in 0..255 at (x, y)
  std::array<int, 3> at(int x, int y) const {
    const unsigned char* d = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    const auto* p = reinterpret_cast<const uint32_t*>(d + y * stride) + x;
    return {static_cast<int>((*p >> 16) & 0xff), static_cast<int>((*p >> 8) & 0xff),
            static_cast<int>(*p & 0xff)};
  }
};

// The PNG has the requested size; the design-point marker is drawn in its series colour where
// (30 deg, 60 mm) maps, and the band tints the area between its edges.
TEST(ChartPainter, SeriesLandWhereTheirDataSays) {
  const Chart chart = sample_chart();
  const std::string png = chart_png(chart, 800, 500);
  if (const char* dump = std::getenv("FEEDFLOW_DUMP_CHART")) std::ofstream(dump, std::ios::binary) << png;
  Pixels px(png);
  ASSERT_EQ(cairo_surface_status(px.surface), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(px.surface), 800);
  EXPECT_EQ(cairo_image_surface_get_height(px.surface), 500);
  // Plot area in points (scale 2): left 52, right 400-12, top 22, bottom 250-34. The ticks
  // span 10..40 deg and 10..60 mm; the axes add 3 % air at each end.
  const double left = 52, right = 388, top = 22, bottom = 216;
  auto map = [&](double xv, double yv) {
    const double x0 = 10 - 0.9, x1 = 40 + 0.9, y0 = 10 - 1.5, y1 = 60 + 1.5;
    return std::pair<int, int>{static_cast<int>(2 * (left + (xv - x0) / (x1 - x0) * (right - left))),
                               static_cast<int>(2 * (bottom - (yv - y0) / (y1 - y0) * (bottom - top)))};
  };
  const auto [mx, my] = map(30, 59);  // inside the diamond marker at (30 deg, 60 mm)
  const auto marker = px.at(mx, my);
  const auto expected = style::kSeries[2];
  EXPECT_NEAR(marker[0], expected.r * 255, 30);
  EXPECT_NEAR(marker[1], expected.g * 255, 30);
  EXPECT_NEAR(marker[2], expected.b * 255, 30);
  const auto [bx, by] = map(22, 16);  // inside the band, below the Jenike line
  const auto band = px.at(bx, by);
  EXPECT_LT(band[0], 250);  // tinted, not white
  EXPECT_GT(band[0], 150);  // but light: a translucent fill
  const auto [ox, oy] = map(27, 45);  // above the band, between grid lines: background
  EXPECT_EQ(px.at(ox, oy), (std::array<int, 3>{255, 255, 255}));
}

// Charts with no series, one point, gaps (NaN) or a log axis render without error.
TEST(ChartPainter, DegenerateChartsRender) {
  Chart empty;
  empty.title = "empty";
  EXPECT_FALSE(chart_png(empty, 200, 150).empty());
  Chart one = sample_chart();
  one.series = {{"one", SeriesStyle::points, {1}, {1}, {}}};
  EXPECT_FALSE(chart_png(one, 200, 150).empty());
  Chart gaps = sample_chart();
  gaps.series[1].y[1] = std::nan("");
  gaps.y.logarithmic = true;
  EXPECT_FALSE(chart_png(gaps, 200, 150).empty());
  EXPECT_EQ(axis_title({"flow factor", ""}), "flow factor");
  EXPECT_EQ(axis_title({"semi-angle", "deg"}), "semi-angle [deg]");
}

// The legend goes to the first of the corners (top right, top left, bottom right, bottom left)
// that hides the fewest marks: top right when it is empty; bottom left when points crowd the
// other three corners (a rising series would hide its slowest-and-worst point otherwise).
TEST(ChartPainter, TheLegendAvoidsTheMarks) {
  const DeviceBox plot{0, 0, 200, 100};
  const LegendPlace empty = legend_place(plot, 60, 30, {{10, 90}});
  EXPECT_DOUBLE_EQ(empty.x, 200 - 60 - 4);
  EXPECT_DOUBLE_EQ(empty.y, 4);
  const LegendPlace crowded =
      legend_place(plot, 60, 30, {{190, 10}, {10, 10}, {190, 90}, {180, 20}});
  EXPECT_DOUBLE_EQ(crowded.x, 4);
  EXPECT_DOUBLE_EQ(crowded.y, 100 - 30 - 4);
}

}  // namespace
}  // namespace feedflow
