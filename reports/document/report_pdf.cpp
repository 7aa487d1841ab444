#include "reports/document/report_pdf.hpp"

#include <cairo-pdf.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "reports/document/page_layout.hpp"

namespace feedflow {
namespace {

style::Colour colour_of(Tone tone) {
  switch (tone) {
    case Tone::normal: return style::kText;
    case Tone::muted: return {0.4, 0.4, 0.4};
    case Tone::pass: return style::kPass;
    case Tone::marginal: return style::kMarginal;
    case Tone::fail: return style::kFail;
    case Tone::unknown: return style::kUnknown;
  }
  return style::kText;
}

// Lays the content out on `cr`; returns the pages used.
int lay_out(cairo_t* cr, const ReportContent& content, int total_pages) {
  PageLayout page(cr, content.header, total_pages);
  for (const auto& block : content.blocks) {
    std::visit(
        [&](const auto& b) {
          using T = std::decay_t<decltype(b)>;
          if constexpr (std::is_same_v<T, ReportHeading>) page.heading(b.text, b.level);
          if constexpr (std::is_same_v<T, ReportParagraph>)
            page.paragraph(b.text, b.bold ? 12.0 : 9.5, colour_of(b.tone), b.bold);
          if constexpr (std::is_same_v<T, ReportBullets>) page.bullets(b.items);
          if constexpr (std::is_same_v<T, ReportTable>) page.table(b.header, b.rows, b.proportions);
          if constexpr (std::is_same_v<T, ReportChart>) page.chart(b.chart, 250, b.chart.note);
          if constexpr (std::is_same_v<T, ReportImage>) page.image(b.png, page.text_width(), b.caption);
        },
        block);
  }
  return page.finish();
}

}  // namespace

RenderedPdf render_report_pdf(const ReportContent& content) {
  // Pass 1 counts the pages on a scratch surface; pass 2 draws with "page i of N".
  cairo_surface_t* scratch = cairo_pdf_surface_create_for_stream(
      [](void*, const unsigned char*, unsigned int) { return CAIRO_STATUS_SUCCESS; }, nullptr,
      PageLayout::kPageWidth, PageLayout::kPageHeight);
  cairo_t* counting = cairo_create(scratch);
  const int pages = lay_out(counting, content, 0);
  cairo_destroy(counting);
  cairo_surface_destroy(scratch);

  RenderedPdf pdf;
  pdf.pages = pages;
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(
      [](void* closure, const unsigned char* data, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &pdf.bytes, PageLayout::kPageWidth, PageLayout::kPageHeight);
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, content.title.c_str());
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "feedflow");
  cairo_t* cr = cairo_create(surface);
  lay_out(cr, content, pages);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const auto status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cannot render the PDF report: ") + cairo_status_to_string(status));
  return pdf;
}

int write_report_pdf(const ReportContent& content, const std::filesystem::path& path) {
  const RenderedPdf pdf = render_report_pdf(content);
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  const auto temporary = std::filesystem::path(path.string() + ".tmp");
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(pdf.bytes.data(), static_cast<std::streamsize>(pdf.bytes.size()));
    out.flush();
    if (!out) {
      std::filesystem::remove(temporary, ec);
      throw std::runtime_error("cannot write " + path.string());
    }
  }
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw std::runtime_error("cannot write " + path.string() + ": " + ec.message());
  }
  return pdf.pages;
}

}  // namespace feedflow
