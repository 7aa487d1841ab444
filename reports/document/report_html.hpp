#pragma once
// The design report as one self-contained HTML file (styles inline, images embedded).
#include <string>

#include "reports/document/report_content.hpp"

namespace feedflow {

std::string report_html(const ReportContent& content);

}  // namespace feedflow
