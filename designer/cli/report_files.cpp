#include "designer/cli/report_files.hpp"

#include <chrono>
#include <ctime>

#include "designer/design/hopper_snapshot.hpp"
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

std::vector<OutputFile> report_files(const std::filesystem::path& folder,
                                     const DesignRecord& record,
                                     std::vector<ReportImage> simulation) {
  std::vector<ReportImage> pictures;
  if (auto picture = hopper_stress_snapshot(record)) pictures.push_back(std::move(*picture));
  for (auto& p : simulation) pictures.push_back(std::move(p));
  const ReportContent content = design_report_content(record, pictures, utc_now());
  return {{folder / "report.pdf", render_report_pdf(content).bytes, "--out"},
          {folder / "report.html", report_html(content), "--out"}};
}

}  // namespace feedflow
