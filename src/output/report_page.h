// A report as a list of blocks (headings, paragraphs, tables, pictures, charts, 3D views), written
// as Markdown (report.md) and as one self-contained HTML page (its pictures embedded, HtmlPngImage;
// its charts inline SVG, src/output/svg_chart.h; its 3D views three.js with the drape.glb files
// embedded, src/output/viewer3d.h): the one page writer of every HTML report — `drape
// compare`'s and `drape fit`'s report.html, sweep.html, the drops report and the fabrics report.
#ifndef DRAPE_SRC_OUTPUT_REPORT_PAGE_H_
#define DRAPE_SRC_OUTPUT_REPORT_PAGE_H_

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "src/output/viewer3d.h"

namespace drape {

// Text may hold Markdown's `code` spans (HTML: <code>) and links, [text](target) (HTML: <a>);
// nothing else of Markdown is interpreted.
struct ReportBlock {
  enum class Kind { kHeading, kText, kTable, kImage, kChart, kPreformatted, kView3d };
  Kind kind = Kind::kText;
  std::string text;  // heading, paragraph, picture or chart caption, preformatted text
  std::vector<std::vector<std::string>> rows;  // table: header row first
  std::vector<std::string> row_colours;        // table: a colour key (■) before each data row's
                                               // first cell, a chart's series colours; or none
  std::string image;                           // picture: a PNG's path relative to the report
  std::string svg;                             // chart: its SVG text (SvgPicture::Close)
  std::vector<ViewerShape> shapes;             // 3D view: the drape.glb files it shows
};

ReportBlock HeadingBlock(const std::string& text);
ReportBlock TextBlock(const std::string& text);
ReportBlock TableBlock(std::vector<std::vector<std::string>> rows);
ReportBlock ImageBlock(const std::string& path, const std::string& caption);
ReportBlock ChartBlock(const std::string& svg, const std::string& caption);
// A 3D view of `shapes` (Markdown: links to the files; HTML: src/output/viewer3d.h).
ReportBlock View3dBlock(std::vector<ViewerShape> shapes, const std::string& caption);

// "[text](target)": a link in a block's text or a table cell.
std::string ReportLink(const std::string& text, const std::string& target);
ReportBlock PreformattedBlock(const std::string& text);

// The first heading is the title (#), the others sections (##); tables align their first and last
// columns left, the others (numbers) right; pictures are linked; charts are inline SVG (Markdown
// lets HTML through).
void WriteMarkdownReport(const std::vector<ReportBlock>& blocks, std::ostream& out);

// The same page in HTML, the pictures read from `folder` and embedded.
void WriteHtmlReport(const std::vector<ReportBlock>& blocks, const std::filesystem::path& folder,
                     std::ostream& out);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_REPORT_PAGE_H_
