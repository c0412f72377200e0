// A report as a list of blocks (headings, paragraphs, tables, pictures), written once as Markdown
// (report.md) and once as one self-contained HTML page (its pictures embedded, HtmlPngImage): the
// one page writer of `drape compare`'s and `drape fit`'s reports.
#ifndef DRAPE_SRC_OUTPUT_REPORT_PAGE_H_
#define DRAPE_SRC_OUTPUT_REPORT_PAGE_H_

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace drape {

// Text may hold Markdown's `code` spans (HTML: <code>); nothing else of Markdown is interpreted.
struct ReportBlock {
  enum class Kind { kHeading, kText, kTable, kImage };
  Kind kind = Kind::kText;
  std::string text;                            // heading, paragraph or picture caption
  std::vector<std::vector<std::string>> rows;  // table: header row first
  std::string image;                           // picture: a PNG's path relative to the report
};

ReportBlock HeadingBlock(const std::string& text);
ReportBlock TextBlock(const std::string& text);
ReportBlock TableBlock(std::vector<std::vector<std::string>> rows);
ReportBlock ImageBlock(const std::string& path, const std::string& caption);

// The first heading is the title (#), the others sections (##); tables align their first and last
// columns left, the others (numbers) right; pictures are linked.
void WriteMarkdownReport(const std::vector<ReportBlock>& blocks, std::ostream& out);

// The same page in HTML, the pictures read from `folder` and embedded.
void WriteHtmlReport(const std::vector<ReportBlock>& blocks, const std::filesystem::path& folder,
                     std::ostream& out);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_REPORT_PAGE_H_
