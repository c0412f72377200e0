// Text and pictures put into HTML (and SVG) pages: the one escaper and the one image embedder of
// the HTML reports (compare's report.html, sweep.html, the drops report, fit's report.html).
#ifndef DRAPE_SRC_OUTPUT_HTML_TEXT_H_
#define DRAPE_SRC_OUTPUT_HTML_TEXT_H_

#include <filesystem>
#include <string>

namespace drape {

// `text` with <, >, & and " escaped: safe in an element's text and in a quoted attribute.
std::string HtmlText(const std::string& text);

// `bytes` in base64 (RFC 4648, padded with '=').
std::string Base64(const std::string& bytes);

// An <img> of the PNG file `png`, embedded as a data: URI so that the page stands alone (it can be
// mailed or moved without its plots folder); `alt` escaped. An unreadable file gives an empty
// image with its alt text.
std::string HtmlPngImage(const std::filesystem::path& png, const std::string& alt);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_HTML_TEXT_H_
