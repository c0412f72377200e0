// How drape's PNG pictures carry its version: a tEXt chunk `Software: drape <version>` (PNG
// specification, section 11.3.4) put in after the header chunk, since neither cairo nor gnuplot
// writes one. drape.png, shadow.png, fit.png and the reports' plots carry it.
#ifndef DRAPE_SRC_OUTPUT_PNG_TEXT_H_
#define DRAPE_SRC_OUTPUT_PNG_TEXT_H_

#include <filesystem>
#include <map>
#include <string>

namespace drape {

// `png` with a tEXt chunk `keyword` (1 to 79 Latin-1 characters) = `text` after its IHDR chunk;
// unchanged if it does not start as a PNG does.
std::string PngWithText(const std::string& png, const std::string& keyword,
                        const std::string& text);

// `png` with `Software: drape <version>`; the file rewritten so, atomically (nothing if it cannot
// be read or is no PNG; std::runtime_error if it cannot be written).
std::string PngWithDrapeVersion(const std::string& png);
void AddDrapeVersionToPngFile(const std::filesystem::path& path);

// The tEXt chunks of `png`, keyword to text.
std::map<std::string, std::string> PngTexts(const std::string& png);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_PNG_TEXT_H_
