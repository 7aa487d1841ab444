// The design report: a valid PDF with the expected pages, text and embedded images, and a
// self-contained HTML twin.
#include <gtest/gtest.h>

#include <cairo.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "reports/document/report_content.hpp"
#include "reports/document/report_html.hpp"
#include "reports/document/report_pdf.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

std::string run(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  pclose(pipe);
  return out;
}

std::string solid_png(int w, int h) {  // a synthetic "snapshot"
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, 0.2, 0.4, 0.8);
  cairo_paint(cr);
  cairo_destroy(cr);
  std::string png;
  cairo_surface_write_to_png_stream(
      s,
      [](void* c, const unsigned char* d, unsigned int n) {
        static_cast<std::string*>(c)->append(reinterpret_cast<const char*>(d), n);
        return CAIRO_STATUS_SUCCESS;
      },
      &png);
  cairo_surface_destroy(s);
  return png;
}

DesignRecord record() {
  DesignRecord r;
  r.feedflow_version = "0.1.0";
  r.case_name = "pilot_hopper";
  r.case_file = "cases/pilot_hopper.toml";
  r.description = "Seed pilot wedge hopper";
  r.inputs = {{"hopper.semi_angle", 0.5236, "rad", "30 deg", ""},
              {"material.name", std::string("loblolly_pine"), "", "loblolly_pine", "built-in"},
              {"material.bulk.density", 290.0, "kg/m^3", "290 kg/m^3", "seed FEM deck"}};
  r.results = {{"critical_outlet_width", {23.6, "mm", 18.0, 31.0, "Jenike/Enstad closed form", Rung::L0, ""}}};
  r.verdict = {VerdictStatus::pass, {"outlet 60 mm is 2.5 x the critical width 23.6 mm"}};
  Chart c;
  c.id = "bc";
  c.title = "Critical outlet width against semi-angle";
  c.x = {"semi-angle", "deg"};
  c.y = {"critical outlet width", "mm"};
  c.series = {{"Jenike", SeriesStyle::line, {10, 20, 30}, {20, 22, 24}, {}}};
  c.note = "Jenike errs on the safe side (wider).";
  r.charts = {c, c};
  r.assumptions = {"plane flow: the slot is long (L >= 3 B)"};
  r.command_line = "feedflow design cases/pilot_hopper.toml --report";
  r.wall_seconds = 0.002;
  return r;
}

// The PDF opens in poppler, has real text (title, result, verdict, material source, provenance)
// and the snapshot as an embedded image.
TEST(DesignReport, PdfHasTextPagesAndImages) {
  const fs::path dir = fs::temp_directory_path() / "feedflow_report_test";
  fs::remove_all(dir);
  const auto content = design_report_content(record(), {{solid_png(320, 200), "snapshot at t = 1 s"}},
                                             "2026-01-01 00:00 UTC");
  const int pages = write_report_pdf(content, dir / "report.pdf");
  ASSERT_TRUE(fs::exists(dir / "report.pdf"));
  EXPECT_FALSE(fs::exists(dir / "report.pdf.tmp"));
  const std::string info = run("pdfinfo '" + (dir / "report.pdf").string() + "'");
  EXPECT_NE(info.find("Pages:           " + std::to_string(pages)), std::string::npos) << info;
  EXPECT_NE(info.find("Design report: pilot_hopper"), std::string::npos) << info;
  EXPECT_GE(pages, 2);
  const std::string text = run("pdftotext -layout '" + (dir / "report.pdf").string() + "' -");
  for (const char* expected : {"Design report: pilot_hopper", "PASS", "critical outlet width",
                               "23.6 mm", "18 .. 31 mm", "Jenike/Enstad closed form", "seed FEM deck",
                               "Critical outlet width against semi-angle", "semi-angle [deg]",
                               "plane flow: the slot is long", "feedflow design cases/pilot_hopper.toml",
                               "page 1 of " })
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  const std::string images = run("pdfimages -list '" + (dir / "report.pdf").string() + "'");
  EXPECT_NE(images.find("image     320   200"), std::string::npos) << images;
  fs::remove_all(dir);
}

// A long table breaks across pages and repeats its header.
TEST(DesignReport, LongTablesBreakWithHeader) {
  DesignRecord r = record();
  for (int i = 0; i < 120; ++i)
    r.inputs.push_back({"material.extra.p" + std::to_string(i), 1.0, "", "1", "test source"});
  const fs::path file = fs::temp_directory_path() / "feedflow_long_report.pdf";
  const int pages = write_report_pdf(design_report_content(r, {}, "today"), file);
  const std::string text = run("pdftotext '" + file.string() + "' -");
  std::size_t headers = 0;
  for (std::size_t p = text.find("Parameter"); p != std::string::npos; p = text.find("Parameter", p + 1)) ++headers;
  EXPECT_GE(pages, 4);
  EXPECT_GE(headers, 3u) << "the material table spans pages and repeats its header";
  fs::remove(file);
}

// The HTML report is one file: charts and snapshots embedded as data URIs, text escaped.
TEST(DesignReport, HtmlIsSelfContained) {
  DesignRecord r = record();
  r.verdict.reasons = {"outlet < 3 x B & more"};
  const std::string html =
      report_html(design_report_content(r, {{solid_png(8, 8), "snap"}}, "today"));
  std::size_t images = 0;
  for (std::size_t p = html.find("data:image/png;base64,"); p != std::string::npos;
       p = html.find("data:image/png;base64,", p + 1))
    ++images;
  EXPECT_EQ(images, 3u);  // two charts and one snapshot
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_NE(html.find("outlet &lt; 3 x B &amp; more"), std::string::npos);
  EXPECT_NE(html.find("class=\"pass\""), std::string::npos);
}

// A record of no case (the bench over the seed's cases) reads as a report, not a design of one
// piece of equipment: no equipment, verdict, inputs, material sheet or case file, its verdict's
// notes under "Notes".
TEST(DesignReport, ARecordOfNoCaseHasNoEquipmentVerdictOrInputs) {
  DesignRecord r = record();
  r.case_name = "bench";
  r.case_file.clear();
  r.inputs.clear();
  r.verdict = {VerdictStatus::unknown, {"note: a benchmark, not a design check"}};
  const auto content = design_report_content(r, {}, "today");
  EXPECT_EQ(content.title, "Report: bench");
  EXPECT_EQ(content.header.find("hopper"), std::string::npos) << content.header;
  std::string text;
  for (const auto& block : content.blocks) {
    if (const auto* h = std::get_if<ReportHeading>(&block)) text += "#" + h->text + "\n";
    if (const auto* p = std::get_if<ReportParagraph>(&block)) text += p->text + "\n";
    if (const auto* b = std::get_if<ReportBullets>(&block))
      for (const auto& item : b->items) text += item + "\n";
  }
  for (const char* absent :
       {"#Verdict", "#Inputs", "#Material data sheet", "Equipment:", "case file:", "UNKNOWN"})
    EXPECT_EQ(text.find(absent), std::string::npos) << absent << " in\n" << text;
  for (const char* present :
       {"#Notes", "note: a benchmark, not a design check", "#Results", "feedflow 0.1.0"})
    EXPECT_NE(text.find(present), std::string::npos) << present << " not in\n" << text;
}

}  // namespace
}  // namespace feedflow
