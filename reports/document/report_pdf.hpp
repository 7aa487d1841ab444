#pragma once
// The design report as a PDF (cairo PDF surface: real text, vector charts, embedded images).
#include <filesystem>
#include <string>

#include "reports/document/report_content.hpp"

namespace feedflow {

struct RenderedPdf {
  std::string bytes;
  int pages = 0;
};

// The PDF in memory, for a caller that writes it with other files all or none.
RenderedPdf render_report_pdf(const ReportContent& content);

// Writes the PDF to `path` (atomically: whole or not at all); returns the page count.
int write_report_pdf(const ReportContent& content, const std::filesystem::path& path);

}  // namespace feedflow
