#pragma once
// A small flow layout for A4 reports on a cairo surface: headings, wrapped paragraphs, bullet
// lists, tables that break between rows, charts and images, with a running header and a
// "page i of N" footer. Run it once to count pages, then again to draw (see design_report_pdf).
#include <cairo.h>

#include <string>
#include <vector>

#include "models/core/chart.hpp"
#include "reports/plot/plot_style.hpp"

namespace feedflow {

class PageLayout {
 public:
  static constexpr double kPageWidth = 595.276;   // A4 in points
  static constexpr double kPageHeight = 841.890;
  static constexpr double kMargin = 56.0;

  // `cr` draws on the surface; `total_pages` is 0 while counting.
  PageLayout(cairo_t* cr, std::string header, int total_pages);

  void heading(const std::string& text, int level = 1);
  void paragraph(const std::string& text, double size = 9.5, style::Colour colour = style::kText,
                 bool bold = false);
  void bullets(const std::vector<std::string>& items, double size = 9.5);
  // Columns share the text width in the given proportions; the header row repeats after a break.
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
             const std::vector<double>& proportions, double size = 8.5);
  void chart(const Chart& chart, double height, const std::string& caption);
  // PNG bytes drawn at `width` points wide (aspect kept).
  void image(const std::string& png, double width, const std::string& caption);
  void space(double points) { y_ += points; }
  void new_page();
  // Draws the footer of the last page; returns the number of pages used.
  int finish();

  double text_width() const { return kPageWidth - 2 * kMargin; }

 private:
  void ensure(double height);
  void caption(const std::vector<std::string>& lines);  // small grey lines under a figure
  void start_page();
  void end_page();
  std::vector<std::string> wrap(const std::string& text, double width, double size, bool bold);
  void set_font(double size, bool bold);
  double line_height(double size) const { return size * 1.35; }

  cairo_t* cr_;
  std::string header_;
  int total_pages_;
  int page_ = 0;
  double y_ = 0.0;
};

}  // namespace feedflow
