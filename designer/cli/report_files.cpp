#include "designer/cli/report_files.hpp"

#include <chrono>
#include <ctime>
#include <stdexcept>

#include "designer/design/hopper_snapshot.hpp"
#include "models/core/errors.hpp"
#include "models/os/atomic_file.hpp"
#include "reports/document/report_content.hpp"
#include "reports/document/report_html.hpp"
#include "reports/document/report_pdf.hpp"

namespace feedflow {
namespace {

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

}  // namespace

std::vector<std::filesystem::path> write_report_files(const std::filesystem::path& folder,
                                                      const DesignRecord& record) {
  std::vector<ReportImage> pictures;
  if (auto picture = hopper_stress_snapshot(record)) pictures.push_back(std::move(*picture));
  const ReportContent content = design_report_content(record, pictures, utc_now());
  const auto pdf = folder / "report.pdf";
  const auto html = folder / "report.html";
  try {
    write_report_pdf(content, pdf);
    write_file_atomically(html, report_html(content));
  } catch (const std::runtime_error& e) {
    throw InputError("--out", "", e.what());
  }
  return {pdf, html};
}

}  // namespace feedflow
