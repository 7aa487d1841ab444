#pragma once
// The design report as a PDF (cairo PDF surface: real text, vector charts, embedded images).
#include <filesystem>

#include "reports/document/report_content.hpp"

namespace feedflow {

// Writes the PDF to `path` (atomically: whole or not at all); returns the page count.
int write_report_pdf(const ReportContent& content, const std::filesystem::path& path);

}  // namespace feedflow
