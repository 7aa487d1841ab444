#include "reports/plot/chart_painter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "reports/plot/axis_ticks.hpp"
#include "reports/plot/plot_style.hpp"

namespace feedflow {
namespace {

void set_colour(cairo_t* cr, const style::Colour& c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

void text_at(cairo_t* cr, const std::string& text, double x, double y, double size,
             double align_x, double align_y, bool bold = false) {
  cairo_select_font_face(cr, style::kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - align_x * e.width - e.x_bearing, y - align_y * e.height - e.y_bearing);
  cairo_show_text(cr, text.c_str());
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v, bool logarithmic) {
    if (!std::isfinite(v) || (logarithmic && v <= 0)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return lo > hi; }
};

// Maps data to device coordinates along one axis.
struct Scale {
  AxisTicks ticks;
  bool logarithmic = false;
  double lower = 0, upper = 1;  // axis range: the ticks' range with a little air
  double device_lo = 0, device_hi = 1;
  double operator()(double v) const {
    const double a = logarithmic ? std::log10(lower) : lower;
    const double b = logarithmic ? std::log10(upper) : upper;
    const double t = ((logarithmic ? std::log10(v) : v) - a) / (b - a);
    return device_lo + t * (device_hi - device_lo);
  }
};

Scale make_scale(const Range& r, bool logarithmic, double lo, double hi, int target) {
  Scale s;
  s.logarithmic = logarithmic;
  const Range data = r.empty() ? Range{logarithmic ? 1.0 : 0.0, logarithmic ? 10.0 : 1.0} : r;
  s.ticks = logarithmic ? log_ticks(data.lo, data.hi) : linear_ticks(data.lo, data.hi, target);
  s.lower = s.ticks.lower;
  s.upper = s.ticks.upper;
  if (!logarithmic) {  // a little air so no point sits on the frame
    const double pad = 0.03 * (s.upper - s.lower);
    s.lower -= pad;
    s.upper += pad;
  }
  s.device_lo = lo;
  s.device_hi = hi;
  return s;
}

void draw_series(cairo_t* cr, const ChartSeries& s, const Scale& sx, const Scale& sy,
                 const style::Colour& colour) {
  const std::size_t n = std::min(s.x.size(), s.y.size());
  auto finite = [&](std::size_t i) {
    return std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && (!sx.logarithmic || s.x[i] > 0) &&
           (!sy.logarithmic || s.y[i] > 0);
  };
  switch (s.style) {
    case SeriesStyle::band: {
      if (s.y_upper.size() != n || n == 0) return;
      // Each run of points with both edges finite is one filled polygon; gaps split the band.
      auto usable = [&](std::size_t i) { return finite(i) && std::isfinite(s.y_upper[i]) && (!sy.logarithmic || s.y_upper[i] > 0); };
      set_colour(cr, colour, 0.18);
      for (std::size_t begin = 0; begin < n;) {
        if (!usable(begin)) { ++begin; continue; }
        std::size_t end = begin;
        while (end < n && usable(end)) ++end;
        cairo_new_path(cr);
        for (std::size_t i = begin; i < end; ++i) cairo_line_to(cr, sx(s.x[i]), sy(s.y[i]));
        for (std::size_t i = end; i-- > begin;) cairo_line_to(cr, sx(s.x[i]), sy(s.y_upper[i]));
        cairo_close_path(cr);
        cairo_fill(cr);
        begin = end;
      }
      return;
    }
    case SeriesStyle::points:
    case SeriesStyle::marker: {
      const double r = s.style == SeriesStyle::marker ? 4.5 : 2.4;
      for (std::size_t i = 0; i < n; ++i) {
        if (!finite(i)) continue;
        const double px = sx(s.x[i]), py = sy(s.y[i]);
        cairo_new_path(cr);
        if (s.style == SeriesStyle::marker) {  // a diamond: the design point
          cairo_move_to(cr, px, py - r);
          cairo_line_to(cr, px + r, py);
          cairo_line_to(cr, px, py + r);
          cairo_line_to(cr, px - r, py);
          cairo_close_path(cr);
        } else {
          cairo_arc(cr, px, py, r, 0, 2 * M_PI);
        }
        set_colour(cr, colour);
        cairo_fill(cr);
      }
      return;
    }
    case SeriesStyle::line:
    case SeriesStyle::dashed: {
      cairo_new_path(cr);
      bool pen_down = false;
      for (std::size_t i = 0; i < n; ++i) {
        if (!finite(i)) {  // a gap: the model has no answer there
          pen_down = false;
          continue;
        }
        if (pen_down)
          cairo_line_to(cr, sx(s.x[i]), sy(s.y[i]));
        else
          cairo_move_to(cr, sx(s.x[i]), sy(s.y[i]));
        pen_down = true;
      }
      set_colour(cr, colour);
      cairo_set_line_width(cr, style::kLineWidth);
      const double dash[] = {5.0, 3.0};
      cairo_set_dash(cr, dash, s.style == SeriesStyle::dashed ? 2 : 0, 0);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      return;
    }
  }
}

void draw_legend_entry(cairo_t* cr, const ChartSeries& s, const style::Colour& colour, double x,
                       double y) {
  set_colour(cr, colour, s.style == SeriesStyle::band ? 0.25 : 1.0);
  if (s.style == SeriesStyle::band) {
    cairo_rectangle(cr, x, y - 3.5, 16, 7);
    cairo_fill(cr);
  } else if (s.style == SeriesStyle::marker) {
    cairo_move_to(cr, x + 8, y - 4);
    cairo_line_to(cr, x + 12, y);
    cairo_line_to(cr, x + 8, y + 4);
    cairo_line_to(cr, x + 4, y);
    cairo_close_path(cr);
    cairo_fill(cr);
  } else if (s.style == SeriesStyle::points) {
    cairo_arc(cr, x + 8, y, 2.8, 0, 2 * M_PI);
    cairo_fill(cr);
  } else {
    const double dash[] = {5.0, 3.0};
    cairo_set_dash(cr, dash, s.style == SeriesStyle::dashed ? 2 : 0, 0);
    cairo_set_line_width(cr, style::kLineWidth);
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x + 16, y);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  set_colour(cr, style::kText);
  text_at(cr, s.label, x + 21, y, style::kTickSize, 0.0, 0.5);
}

style::Colour colour_of(const ChartSeries& s, std::size_t position) {
  const std::size_t index = s.colour >= 0 ? static_cast<std::size_t>(s.colour) : position;
  return style::kSeries[index % style::kSeries.size()];
}

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

LegendPlace legend_place(const DeviceBox& plot, double box_width, double box_height,
                         const std::vector<std::pair<double, double>>& marks) {
  constexpr double kInset = 4.0;
  const LegendPlace corners[] = {
      {plot.right - box_width - kInset, plot.top + kInset},
      {plot.left + kInset, plot.top + kInset},
      {plot.right - box_width - kInset, plot.bottom - box_height - kInset},
      {plot.left + kInset, plot.bottom - box_height - kInset}};
  LegendPlace best = corners[0];
  std::size_t fewest = marks.size() + 1;
  for (const LegendPlace& c : corners) {
    std::size_t covered = 0;
    for (const auto& [mx, my] : marks)
      covered += mx >= c.x && mx <= c.x + box_width && my >= c.y && my <= c.y + box_height;
    if (covered < fewest) {
      fewest = covered;
      best = c;
    }
  }
  return best;
}

std::string axis_title(const ChartAxis& axis) {
  return axis.unit.empty() ? axis.label : axis.label + " [" + axis.unit + "]";
}

void paint_chart(cairo_t* cr, const Chart& chart, double x, double y, double width, double height) {
  cairo_save(cr);
  Range rx, ry;
  for (const auto& s : chart.series) {
    for (double v : s.x) rx.add(v, chart.x.logarithmic);
    for (double v : s.y) ry.add(v, chart.y.logarithmic);
    for (double v : s.y_upper) ry.add(v, chart.y.logarithmic);
  }
  const double left = x + 52, right = x + width - 12, top = y + 22, bottom = y + height - 34;
  const Scale sx = make_scale(rx, chart.x.logarithmic, left, right, 7);
  const Scale sy = make_scale(ry, chart.y.logarithmic, bottom, top, 6);

  set_colour(cr, style::kText);
  text_at(cr, chart.title, x + width / 2, y + 2, style::kTitleSize, 0.5, 0.0, true);

  // Grid, ticks and tick labels.
  cairo_set_line_width(cr, 0.5);
  for (std::size_t i = 0; i < sx.ticks.values.size(); ++i) {
    const double px = sx(sx.ticks.values[i]);
    set_colour(cr, style::kGrid);
    cairo_move_to(cr, px, top);
    cairo_line_to(cr, px, bottom);
    cairo_stroke(cr);
    set_colour(cr, style::kText);
    text_at(cr, sx.ticks.labels[i], px, bottom + 4, style::kTickSize, 0.5, 0.0);
  }
  for (std::size_t i = 0; i < sy.ticks.values.size(); ++i) {
    const double py = sy(sy.ticks.values[i]);
    set_colour(cr, style::kGrid);
    cairo_move_to(cr, left, py);
    cairo_line_to(cr, right, py);
    cairo_stroke(cr);
    set_colour(cr, style::kText);
    text_at(cr, sy.ticks.labels[i], left - 4, py, style::kTickSize, 1.0, 0.5);
  }
  set_colour(cr, style::kAxis);
  cairo_set_line_width(cr, 0.8);
  cairo_rectangle(cr, left, top, right - left, bottom - top);
  cairo_stroke(cr);

  // Axis titles with units.
  set_colour(cr, style::kText);
  text_at(cr, axis_title(chart.x), (left + right) / 2, bottom + 17, style::kLabelSize, 0.5, 0.0);
  cairo_save(cr);
  cairo_translate(cr, x + 8, (top + bottom) / 2);
  cairo_rotate(cr, -M_PI / 2);
  text_at(cr, axis_title(chart.y), 0, 0, style::kLabelSize, 0.5, 0.5);
  cairo_restore(cr);

  // Series, clipped to the plot area; bands first so lines stay on top.
  cairo_save(cr);
  cairo_rectangle(cr, left, top, right - left, bottom - top);
  cairo_clip(cr);
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < chart.series.size(); ++i)
      if ((chart.series[i].style == SeriesStyle::band) == (pass == 0))
        draw_series(cr, chart.series[i], sx, sy, colour_of(chart.series[i], i));
  cairo_restore(cr);

  // Legend, inside the plot where it hides the fewest marks.
  if (!chart.series.empty()) {
    cairo_select_font_face(cr, style::kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, style::kTickSize);
    double widest = 0;
    for (const auto& s : chart.series) {
      cairo_text_extents_t e;
      cairo_text_extents(cr, s.label.c_str(), &e);
      widest = std::max(widest, e.x_advance);
    }
    const double box_w = widest + 30, row = 11, box_h = row * chart.series.size() + 6;
    std::vector<std::pair<double, double>> marks;  // what the box should not hide
    for (const auto& s : chart.series) {
      const auto& upper = s.y_upper.empty() ? s.y : s.y_upper;
      for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
        marks.emplace_back(sx(s.x[k]), sy(s.y[k]));
        if (k < upper.size()) marks.emplace_back(sx(s.x[k]), sy(upper[k]));
        if (k == 0 || s.style == SeriesStyle::points || s.style == SeriesStyle::marker) continue;
        for (int j = 1; j < 16; ++j) {  // along the segment from the previous point
          const double f = j / 16.0;
          marks.emplace_back(sx(s.x[k - 1]) + f * (sx(s.x[k]) - sx(s.x[k - 1])),
                             sy(s.y[k - 1]) + f * (sy(s.y[k]) - sy(s.y[k - 1])));
        }
      }
    }
    const LegendPlace place = legend_place({left, top, right, bottom}, box_w, box_h, marks);
    const double bx = place.x, by = place.y;
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_rectangle(cr, bx, by, box_w, box_h);
    cairo_fill(cr);
    for (std::size_t i = 0; i < chart.series.size(); ++i)
      draw_legend_entry(cr, chart.series[i], colour_of(chart.series[i], i), bx + 4,
                        by + 3 + row * (i + 0.5));
  }
  cairo_restore(cr);
}

std::string chart_png(const Chart& chart, int width, int height) {
  // Drawn at 2x the point size for crisp pixels.
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const double scale = 2.0;
  cairo_scale(cr, scale, scale);
  paint_chart(cr, chart, 0, 0, width / scale, height / scale);
  cairo_destroy(cr);
  std::string png;
  const auto status = cairo_surface_write_to_png_stream(surface, append_bytes, &png);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("chart PNG: ") + cairo_status_to_string(status));
  return png;
}

}  // namespace feedflow
