// The one page writer of the HTML reports (src/output/report_page.h): headings, text with code
// spans and links, tables with a colour key, inline SVG charts and preformatted text, in Markdown
// and in HTML.
#include "src/output/report_page.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace drape {
namespace {

std::vector<ReportBlock> Page() {
  ReportBlock table = TableBlock({{"drop", "files"}, {"1", ReportLink("drop_1", "drop_1/")}});
  table.row_colours = {"#1f77b4"};
  return {HeadingBlock("Drops <3>"),
          TextBlock("run `drape solve` in [the folder](out/a b/); [1, 2] (not a link)"), table,
          ChartBlock("<svg><title>t</title></svg>", "shadows & outlines"),
          PreformattedBlock("disc 18 cm\n<specimen>\n")};
}

TEST(ReportPage, WritesEveryBlockAsHtml) {
  std::ostringstream html;
  WriteHtmlReport(Page(), "", html);
  const std::string page = html.str();
  EXPECT_NE(page.find("<title>Drops &lt;3&gt;</title>"), std::string::npos) << page;
  EXPECT_NE(page.find("<h1>Drops &lt;3&gt;</h1>"), std::string::npos);
  EXPECT_NE(page.find("<p>run <code>drape solve</code> in <a href=\"out/a b/\">the folder</a>; "
                      "[1, 2] (not a link)</p>"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("<tr><td><span style=\"color:#1f77b4\">&#9632;</span> 1</td><td><a "
                      "href=\"drop_1/\">drop_1</a></td></tr>"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("<figure><svg><title>t</title></svg><figcaption>shadows &amp; "
                      "outlines</figcaption></figure>"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("<pre>disc 18 cm\n&lt;specimen&gt;\n</pre>"), std::string::npos) << page;
}

TEST(ReportPage, WritesTheSamePageAsMarkdown) {
  std::ostringstream markdown;
  WriteMarkdownReport(Page(), markdown);
  const std::string page = markdown.str();
  EXPECT_EQ(page.rfind("# Drops <3>\n\n", 0), 0u) << page;
  EXPECT_NE(page.find("| 1 | [drop_1](drop_1/) |\n"), std::string::npos) << page;
  EXPECT_NE(page.find("<figure><svg><title>t</title></svg>"), std::string::npos) << page;
  EXPECT_NE(page.find("```\ndisc 18 cm\n<specimen>\n```\n"), std::string::npos) << page;
}

}  // namespace
}  // namespace drape
