#pragma once
// What a design report says, as a list of blocks (headings, paragraphs, tables, charts,
// images), built once from a design record and then laid out as PDF or HTML.
#include <string>
#include <variant>
#include <vector>

#include "models/core/chart.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

struct ReportHeading {
  std::string text;
  int level = 1;  // 0 title, 1 section, 2 subsection
};
enum class Tone { normal, muted, pass, marginal, fail, unknown };
struct ReportParagraph {
  std::string text;
  Tone tone = Tone::normal;
  bool bold = false;
};
struct ReportBullets {
  std::vector<std::string> items;
};
struct ReportTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<double> proportions;  // relative column widths
};
struct ReportChart {
  Chart chart;
};
struct ReportImage {
  std::string png;  // PNG bytes
  std::string caption;
};

using ReportBlock =
    std::variant<ReportHeading, ReportParagraph, ReportBullets, ReportTable, ReportChart, ReportImage>;

struct ReportContent {
  std::string title;   // "Design report: pilot_hopper"
  std::string header;  // running header of every page
  std::vector<ReportBlock> blocks;
};

// The report of a design record; `snapshots` are rendered images with captions (may be empty);
// `generated` is the date line ("2026-11-22 04:30 UTC").
ReportContent design_report_content(const DesignRecord& record,
                                    const std::vector<ReportImage>& snapshots,
                                    const std::string& generated);

Tone tone_of(VerdictStatus status);

}  // namespace feedflow
