#include "reports/document/page_layout.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "reports/plot/chart_painter.hpp"

namespace feedflow {
namespace {

constexpr double kBodyTop = PageLayout::kMargin + 18;
constexpr double kBodyBottom = PageLayout::kPageHeight - PageLayout::kMargin - 14;

struct PngReader {
  const std::string* bytes;
  std::size_t position;
};

cairo_status_t read_png(void* closure, unsigned char* data, unsigned int length) {
  auto* r = static_cast<PngReader*>(closure);
  if (r->position + length > r->bytes->size()) return CAIRO_STATUS_READ_ERROR;
  std::copy_n(r->bytes->data() + r->position, length, data);
  r->position += length;
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

PageLayout::PageLayout(cairo_t* cr, std::string header, int total_pages)
    : cr_(cr), header_(std::move(header)), total_pages_(total_pages) {
  start_page();
}

void PageLayout::set_font(double size, bool bold) {
  cairo_select_font_face(cr_, style::kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, size);
}

void PageLayout::start_page() {
  ++page_;
  y_ = kBodyTop;
  set_font(7.5, false);
  cairo_set_source_rgb(cr_, 0.4, 0.4, 0.4);
  cairo_move_to(cr_, kMargin, kMargin);
  cairo_show_text(cr_, header_.c_str());
  cairo_set_line_width(cr_, 0.5);
  cairo_move_to(cr_, kMargin, kMargin + 4);
  cairo_line_to(cr_, kPageWidth - kMargin, kMargin + 4);
  cairo_stroke(cr_);
}

void PageLayout::end_page() {
  set_font(7.5, false);
  cairo_set_source_rgb(cr_, 0.4, 0.4, 0.4);
  const std::string footer = "page " + std::to_string(page_) +
                             (total_pages_ > 0 ? " of " + std::to_string(total_pages_) : "");
  cairo_text_extents_t e;
  cairo_text_extents(cr_, footer.c_str(), &e);
  cairo_move_to(cr_, kPageWidth - kMargin - e.x_advance, kPageHeight - kMargin + 6);
  cairo_show_text(cr_, footer.c_str());
  cairo_show_page(cr_);
}

void PageLayout::new_page() {
  end_page();
  start_page();
}

int PageLayout::finish() {
  end_page();
  return page_;
}

void PageLayout::ensure(double height) {
  if (y_ + height > kBodyBottom && y_ > kBodyTop) new_page();
}

std::vector<std::string> PageLayout::wrap(const std::string& text, double width, double size,
                                          bool bold) {
  set_font(size, bold);
  std::vector<std::string> lines;
  std::istringstream paragraphs(text);
  for (std::string para; std::getline(paragraphs, para);) {
    std::istringstream words(para);
    std::string line, word;
    auto fits = [&](const std::string& text) {
      cairo_text_extents_t e;
      cairo_text_extents(cr_, text.c_str(), &e);
      return e.x_advance <= width;
    };
    while (words >> word) {
      const std::string candidate = line.empty() ? word : line + " " + word;
      if (fits(candidate)) {
        line = candidate;
        continue;
      }
      if (!line.empty()) lines.push_back(line);
      line.clear();
      // A word wider than the column (a long dotted key) breaks after '.' or '_', or anywhere.
      while (!fits(word)) {
        std::size_t cut = word.size() - 1;
        while (cut > 1 && !fits(word.substr(0, cut))) --cut;
        const auto soft = word.find_last_of("._", cut - 1);
        if (soft != std::string::npos && soft > 0) cut = soft + 1;
        lines.push_back(word.substr(0, cut));
        word = word.substr(cut);
      }
      line = word;
    }
    lines.push_back(line);
  }
  return lines;
}

void PageLayout::heading(const std::string& text, int level) {
  const double size = level == 0 ? 18 : level == 1 ? 13 : 10.5;
  ensure(line_height(size) * 3);  // keep a heading with what follows
  y_ += level == 0 ? 0 : size * 0.6;
  set_font(size, true);
  cairo_set_source_rgb(cr_, style::kText.r, style::kText.g, style::kText.b);
  cairo_move_to(cr_, kMargin, y_ + size);
  cairo_show_text(cr_, text.c_str());
  y_ += line_height(size) + 2;
}

void PageLayout::paragraph(const std::string& text, double size, style::Colour colour, bool bold) {
  for (const auto& line : wrap(text, text_width(), size, bold)) {
    ensure(line_height(size));
    set_font(size, bold);
    cairo_set_source_rgb(cr_, colour.r, colour.g, colour.b);
    cairo_move_to(cr_, kMargin, y_ + size);
    cairo_show_text(cr_, line.c_str());
    y_ += line_height(size);
  }
  y_ += size * 0.4;
}

void PageLayout::bullets(const std::vector<std::string>& items, double size) {
  for (const auto& item : items) {
    const auto lines = wrap(item, text_width() - 12, size, false);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      ensure(line_height(size));
      set_font(size, false);
      cairo_set_source_rgb(cr_, style::kText.r, style::kText.g, style::kText.b);
      if (i == 0) {
        cairo_move_to(cr_, kMargin + 2, y_ + size);
        cairo_show_text(cr_, "\xE2\x80\xA2");  // bullet
      }
      cairo_move_to(cr_, kMargin + 12, y_ + size);
      cairo_show_text(cr_, lines[i].c_str());
      y_ += line_height(size);
    }
  }
  y_ += size * 0.4;
}

void PageLayout::table(const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows,
                       const std::vector<double>& proportions, double size) {
  if (proportions.size() != header.size())
    throw std::invalid_argument("report table: one proportion per column");
  double total = 0;
  for (double p : proportions) total += p;
  std::vector<double> widths;
  for (double p : proportions) widths.push_back(text_width() * p / total);
  const double pad = 3.0;

  auto wrap_row = [&](const std::vector<std::string>& cells, bool bold) {
    std::vector<std::vector<std::string>> wrapped;
    for (std::size_t c = 0; c < widths.size(); ++c)
      wrapped.push_back(wrap(c < cells.size() ? cells[c] : "", widths[c] - 2 * pad, size, bold));
    return wrapped;
  };
  auto row_height = [&](const std::vector<std::vector<std::string>>& wrapped) {
    std::size_t lines = 1;
    for (const auto& cell : wrapped) lines = std::max(lines, cell.size());
    return lines * line_height(size) + 2 * pad;
  };
  auto paint_row = [&](const std::vector<std::vector<std::string>>& wrapped, bool is_header) {
    const double height = row_height(wrapped);
    if (is_header) {
      cairo_set_source_rgb(cr_, 0.92, 0.94, 0.96);
      cairo_rectangle(cr_, kMargin, y_, text_width(), height);
      cairo_fill(cr_);
    }
    double x = kMargin;
    for (std::size_t c = 0; c < widths.size(); ++c) {
      set_font(size, is_header);
      cairo_set_source_rgb(cr_, style::kText.r, style::kText.g, style::kText.b);
      for (std::size_t l = 0; l < wrapped[c].size(); ++l) {
        cairo_move_to(cr_, x + pad, y_ + pad + size + l * line_height(size));
        cairo_show_text(cr_, wrapped[c][l].c_str());
      }
      x += widths[c];
    }
    y_ += height;
    cairo_set_source_rgb(cr_, 0.8, 0.8, 0.8);
    cairo_set_line_width(cr_, 0.4);
    cairo_move_to(cr_, kMargin, y_);
    cairo_line_to(cr_, kMargin + text_width(), y_);
    cairo_stroke(cr_);
  };

  const auto head = wrap_row(header, true);
  ensure(row_height(head) + line_height(size) * 2);  // never a header alone at a page end
  paint_row(head, true);
  for (const auto& row : rows) {
    const auto wrapped = wrap_row(row, false);
    if (y_ + row_height(wrapped) > kBodyBottom) {  // break between rows, header repeated
      new_page();
      paint_row(head, true);
    }
    paint_row(wrapped, false);
  }
  y_ += size;
}

void PageLayout::caption(const std::vector<std::string>& lines) {
  set_font(8, false);
  cairo_set_source_rgb(cr_, 0.3, 0.3, 0.3);
  for (const auto& line : lines) {
    cairo_move_to(cr_, kMargin, y_ + 8);
    cairo_show_text(cr_, line.c_str());
    y_ += line_height(8);
  }
  y_ += 10;
}

void PageLayout::chart(const Chart& c, double height, const std::string& caption_text) {
  const auto caption_lines = wrap(caption_text, text_width(), 8, false);
  ensure(height + caption_lines.size() * line_height(8) + 6);
  paint_chart(cr_, c, kMargin, y_, text_width(), height);
  y_ += height + 4;
  caption(caption_lines);
}

void PageLayout::image(const std::string& png, double width, const std::string& caption_text) {
  PngReader reader{&png, 0};
  cairo_surface_t* img = cairo_image_surface_create_from_png_stream(read_png, &reader);
  if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(img);
    throw std::runtime_error("report: an image is not a valid PNG");
  }
  const double w = cairo_image_surface_get_width(img), h = cairo_image_surface_get_height(img);
  const double scale = std::min(width, text_width()) / w;
  const auto caption_lines = wrap(caption_text, text_width(), 8, false);
  ensure(h * scale + caption_lines.size() * line_height(8) + 6);
  cairo_save(cr_);
  cairo_translate(cr_, kMargin, y_);
  cairo_scale(cr_, scale, scale);
  cairo_set_source_surface(cr_, img, 0, 0);
  cairo_paint(cr_);
  cairo_restore(cr_);
  cairo_surface_destroy(img);
  y_ += h * scale + 4;
  caption(caption_lines);
}

}  // namespace feedflow
