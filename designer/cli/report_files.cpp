#include "designer/cli/report_files.hpp"

#include <chrono>
#include <ctime>
#include <iostream>
#include <stdexcept>

#include "designer/design/hopper_snapshot.hpp"
#include "designer/simulate/simulation_pictures.hpp"
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

std::vector<OutputFile> report_files(const std::filesystem::path& folder, const DesignRecord& record,
                                     const std::filesystem::path& results_folder) {
  std::vector<ReportImage> pictures;
  if (auto picture = hopper_stress_snapshot(record)) pictures.push_back(std::move(*picture));
  for (const auto& name : record.simulation_runs) {
    // Lexically: the results folder may not exist yet (a report written with its results).
    const std::filesystem::path run = (results_folder / name).lexically_normal();
    try {
      for (auto& p : simulation_pictures(run)) pictures.push_back(std::move(p));
    } catch (const std::runtime_error& e) {
      std::cerr << "feedflow: warning: the report has no pictures of the run in " << run.string()
                << ": " << e.what() << '\n';
    }
  }
  const ReportContent content = design_report_content(record, pictures, utc_now());
  return {{folder / "report.pdf", render_report_pdf(content).bytes, "--out"},
          {folder / "report.html", report_html(content), "--out"}};
}

}  // namespace feedflow
