#include "reports/document/report_html.hpp"

#include <sstream>

#include "reports/plot/chart_painter.hpp"

namespace feedflow {
namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += ch;
    }
  }
  return out;
}

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto b0 = static_cast<unsigned char>(bytes[i]);
    const auto b1 = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0u;
    const auto b2 = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0u;
    out += kAlphabet[b0 >> 2];
    out += kAlphabet[((b0 & 0x03) << 4) | (b1 >> 4)];
    out += i + 1 < bytes.size() ? kAlphabet[((b1 & 0x0f) << 2) | (b2 >> 6)] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[b2 & 0x3f] : '=';
  }
  return out;
}

const char* css_class(Tone tone) {
  switch (tone) {
    case Tone::normal: return "";
    case Tone::muted: return "muted";
    case Tone::pass: return "pass";
    case Tone::marginal: return "marginal";
    case Tone::fail: return "fail";
    case Tone::unknown: return "unknown";
  }
  return "";
}

void figure(std::ostringstream& out, const std::string& png, const std::string& caption) {
  out << "<figure><img alt=\"" << escape(caption) << "\" src=\"data:image/png;base64," << base64(png)
      << "\"><figcaption>" << escape(caption) << "</figcaption></figure>\n";
}

}  // namespace

std::string report_html(const ReportContent& content) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << escape(content.title)
      << "</title>\n<style>body{font-family:'DejaVu Sans',Arial,sans-serif;max-width:52em;margin:2em auto;"
         "color:#1a1a1a;line-height:1.4}table{border-collapse:collapse;width:100%;font-size:0.85em;margin:0.5em 0}"
         "th,td{border-bottom:1px solid #ccc;padding:3px 6px;text-align:left;vertical-align:top}"
         "th{background:#ebf0f5}.muted{color:#666}.pass{color:#008f4c;font-weight:bold}"
         ".marginal{color:#d98c00;font-weight:bold}.fail{color:#cc261a;font-weight:bold}"
         ".unknown{color:#737373;font-weight:bold}figure{margin:1em 0}img{max-width:100%}"
         "figcaption{font-size:0.8em;color:#555}header{font-size:0.8em;color:#666;border-bottom:1px solid #999}"
         "</style></head><body>\n<header>"
      << escape(content.header) << "</header>\n";
  for (const auto& block : content.blocks) {
    std::visit(
        [&](const auto& b) {
          using T = std::decay_t<decltype(b)>;
          if constexpr (std::is_same_v<T, ReportHeading>) {
            const int level = b.level + 1;
            out << "<h" << level << ">" << escape(b.text) << "</h" << level << ">\n";
          }
          if constexpr (std::is_same_v<T, ReportParagraph>)
            out << "<p class=\"" << css_class(b.tone) << "\">" << escape(b.text) << "</p>\n";
          if constexpr (std::is_same_v<T, ReportBullets>) {
            out << "<ul>";
            for (const auto& item : b.items) out << "<li>" << escape(item) << "</li>";
            out << "</ul>\n";
          }
          if constexpr (std::is_same_v<T, ReportTable>) {
            out << "<table><tr>";
            for (const auto& h : b.header) out << "<th>" << escape(h) << "</th>";
            out << "</tr>";
            for (const auto& row : b.rows) {
              out << "<tr>";
              for (const auto& cell : row) out << "<td>" << escape(cell) << "</td>";
              out << "</tr>";
            }
            out << "</table>\n";
          }
          if constexpr (std::is_same_v<T, ReportChart>)
            figure(out, chart_png(b.chart, 1000, 560), b.chart.title + (b.chart.note.empty() ? "" : ". " + b.chart.note));
          if constexpr (std::is_same_v<T, ReportImage>) figure(out, b.png, b.caption);
        },
        block);
  }
  out << "</body></html>\n";
  return out.str();
}

}  // namespace feedflow
