#include "src/output/report_page.h"

#include "src/output/html_text.h"

namespace drape {

namespace {

// HTML of text outside code spans: escaped (HtmlText), its Markdown links [text](target) as <a>.
std::string HtmlWithLinks(const std::string& text) {
  std::string html;
  size_t start = 0;
  for (size_t open = text.find('['); open != std::string::npos; open = text.find('[', open + 1)) {
    const size_t middle = text.find(']', open);
    if (middle == std::string::npos || text.compare(middle, 2, "](") != 0) continue;
    const size_t close = text.find(')', middle);
    if (close == std::string::npos) break;
    html += HtmlText(text.substr(start, open - start)) + "<a href=\"" +
            HtmlText(text.substr(middle + 2, close - middle - 2)) + "\">" +
            HtmlText(text.substr(open + 1, middle - open - 1)) + "</a>";
    start = close + 1;
    open = close;
  }
  return html + HtmlText(text.substr(start));
}

// Text for Markdown (`|` escaped) or HTML (HtmlWithLinks, and Markdown's `code` spans turned into
// <code> elements, so no backtick shows).
std::string Escaped(const std::string& text, bool html) {
  if (!html) {
    std::string escaped;
    for (char c : text) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
    return escaped;
  }
  std::string escaped;
  bool code = false;
  size_t start = 0;
  for (size_t tick = text.find('`'); tick != std::string::npos; tick = text.find('`', start)) {
    const std::string part = text.substr(start, tick - start);
    escaped += (code ? HtmlText(part) : HtmlWithLinks(part)) + (code ? "</code>" : "<code>");
    code = !code;
    start = tick + 1;
  }
  escaped += code ? HtmlText(text.substr(start)) : HtmlWithLinks(text.substr(start));
  return code ? escaped + "</code>" : escaped;
}

// Text without Markdown's backticks (an attribute).
std::string Plain(const std::string& text) {
  std::string plain;
  for (char c : text) {
    if (c != '`') plain += c;
  }
  return plain;
}

void WriteMarkdownTable(const std::vector<std::vector<std::string>>& rows, std::ostream& out) {
  for (size_t r = 0; r < rows.size(); ++r) {
    out << '|';
    for (const std::string& cell : rows[r]) out << ' ' << Escaped(cell, false) << " |";
    out << '\n';
    if (r > 0) continue;
    out << '|';
    for (size_t k = 0; k < rows[0].size(); ++k) {
      out << (k == 0 || k + 1 == rows[0].size() ? "---|" : "--:|");
    }
    out << '\n';
  }
  out << '\n';
}

void WriteHtmlTable(const ReportBlock& table, std::ostream& out) {
  const auto& rows = table.rows;
  out << "<table>\n";
  for (size_t r = 0; r < rows.size(); ++r) {
    out << "<tr>";
    for (size_t k = 0; k < rows[r].size(); ++k) {
      out << (r == 0 ? "<th>" : "<td>");
      if (r > 0 && k == 0 && r - 1 < table.row_colours.size()) {
        out << "<span style=\"color:" << HtmlText(table.row_colours[r - 1]) << "\">&#9632;</span> ";
      }
      out << Escaped(rows[r][k], true) << (r == 0 ? "</th>" : "</td>");
    }
    out << "</tr>\n";
  }
  out << "</table>\n";
}

// A chart as a figure: its SVG inline, its caption below (HTML, which Markdown lets through).
std::string ChartFigure(const ReportBlock& chart) {
  return "<figure>" + chart.svg + "<figcaption>" + Escaped(chart.text, true) +
         "</figcaption></figure>";
}

ReportBlock Block(ReportBlock::Kind kind, const std::string& text) {
  ReportBlock block;
  block.kind = kind;
  block.text = text;
  return block;
}

// A 3D view: three.js's scripts before the page's first view (or, where they cannot be read, the
// reason in the view's place, with links to the files), then the view and its caption.
void WriteHtmlView(const ReportBlock& block, const std::filesystem::path& folder, int index,
                   std::string* scripts_missing, std::ostream& out) {
  if (index == 0) out << ViewerScripts(scripts_missing);
  out << "<figure style=\"display:block\">";
  if (scripts_missing->empty()) {
    out << ViewerHtml(block.shapes, folder, index);
  } else {
    std::string links;
    for (const ViewerShape& shape : block.shapes) {
      links += " " + ReportLink(shape.label, shape.file);
    }
    out << "<p>"
        << Escaped("3D view not drawn: " + *scripts_missing + ". The shapes:" + links, true)
        << "</p>";
  }
  out << "<figcaption>" << Escaped(block.text, true) << "</figcaption></figure>\n";
}

}  // namespace

ReportBlock HeadingBlock(const std::string& text) {
  return Block(ReportBlock::Kind::kHeading, text);
}
ReportBlock TextBlock(const std::string& text) { return Block(ReportBlock::Kind::kText, text); }
ReportBlock TableBlock(std::vector<std::vector<std::string>> rows) {
  ReportBlock block = Block(ReportBlock::Kind::kTable, "");
  block.rows = std::move(rows);
  return block;
}
ReportBlock ImageBlock(const std::string& path, const std::string& caption) {
  ReportBlock block = Block(ReportBlock::Kind::kImage, caption);
  block.image = path;
  return block;
}
ReportBlock ChartBlock(const std::string& svg, const std::string& caption) {
  ReportBlock block = Block(ReportBlock::Kind::kChart, caption);
  block.svg = svg;
  return block;
}
ReportBlock View3dBlock(std::vector<ViewerShape> shapes, const std::string& caption) {
  ReportBlock block = Block(ReportBlock::Kind::kView3d, caption);
  block.shapes = std::move(shapes);
  return block;
}
std::string ReportLink(const std::string& text, const std::string& target) {
  return "[" + text + "](" + target + ")";
}
ReportBlock PreformattedBlock(const std::string& text) {
  return Block(ReportBlock::Kind::kPreformatted, text);
}

void WriteMarkdownReport(const std::vector<ReportBlock>& blocks, std::ostream& out) {
  bool first_heading = true;
  for (const ReportBlock& block : blocks) {
    switch (block.kind) {
      case ReportBlock::Kind::kHeading:
        out << (first_heading ? "# " : "## ") << block.text << "\n\n";
        first_heading = false;
        break;
      case ReportBlock::Kind::kText:
        out << block.text << "\n\n";
        break;
      case ReportBlock::Kind::kImage:
        out << "![" << block.text << "](" << block.image << ")\n\n";
        break;
      case ReportBlock::Kind::kChart:
        out << ChartFigure(block) << "\n\n";
        break;
      case ReportBlock::Kind::kPreformatted:
        out << "```\n"
            << block.text << (block.text.empty() || block.text.back() != '\n' ? "\n" : "")
            << "```\n\n";
        break;
      case ReportBlock::Kind::kTable:
        WriteMarkdownTable(block.rows, out);
        break;
      case ReportBlock::Kind::kView3d:
        out << block.text << " (the 3D view is in report.html; each file opens in Blender or any "
            << "glTF viewer):";
        for (const ViewerShape& shape : block.shapes) {
          out << ' ' << ReportLink(shape.label, shape.file);
        }
        out << "\n\n";
        break;
    }
  }
}

void WriteHtmlReport(const std::vector<ReportBlock>& blocks, const std::filesystem::path& folder,
                     std::ostream& out) {
  std::string title = "drape report";
  for (const ReportBlock& block : blocks) {
    if (block.kind == ReportBlock::Kind::kHeading) {
      title = Plain(block.text);
      break;
    }
  }
  out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << HtmlText(title)
      << "</title><style>body{font-family:sans-serif;max-width:1100px;margin:auto}"
         "table{border-collapse:collapse;font-size:90%}td,th{border:1px solid #bbb;padding:2px "
         "6px}td{text-align:right}td:first-child,td:last-child{text-align:left}img{max-width:100%"
         "}figure{display:inline-block;margin:0.5em;vertical-align:top}</style></head><body>\n";
  bool first_heading = true;
  int views = 0;
  std::string scripts_missing;
  for (const ReportBlock& block : blocks) {
    switch (block.kind) {
      case ReportBlock::Kind::kHeading:
        out << (first_heading ? "<h1>" : "<h2>") << Escaped(block.text, true)
            << (first_heading ? "</h1>\n" : "</h2>\n");
        first_heading = false;
        break;
      case ReportBlock::Kind::kText:
        out << "<p>" << Escaped(block.text, true) << "</p>\n";
        break;
      case ReportBlock::Kind::kImage:
        out << "<figure>" << HtmlPngImage(folder / block.image, Plain(block.text)) << "<figcaption>"
            << Escaped(block.text, true) << "</figcaption></figure>\n";
        break;
      case ReportBlock::Kind::kChart:
        out << ChartFigure(block) << "\n";
        break;
      case ReportBlock::Kind::kPreformatted:
        out << "<pre>" << HtmlText(block.text) << "</pre>\n";
        break;
      case ReportBlock::Kind::kTable:
        WriteHtmlTable(block, out);
        break;
      case ReportBlock::Kind::kView3d:
        WriteHtmlView(block, folder, views++, &scripts_missing, out);
        break;
    }
  }
  out << "</body></html>\n";
}

}  // namespace drape
