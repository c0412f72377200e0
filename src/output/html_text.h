// Text put into HTML (and SVG) pages: the one escaper of sweep.html and the drops report.
#ifndef DRAPE_SRC_OUTPUT_HTML_TEXT_H_
#define DRAPE_SRC_OUTPUT_HTML_TEXT_H_

#include <string>

namespace drape {

// `text` with <, >, & and " escaped: safe in an element's text and in a quoted attribute.
std::string HtmlText(const std::string& text);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_HTML_TEXT_H_
