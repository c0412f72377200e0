#include "src/output/png_text.h"

#include <array>
#include <cstdint>

#include "src/output/atomic_file.h"
#include "src/output/version.h"

namespace drape {

namespace {

constexpr char kSignature[] = "\x89PNG\r\n\x1a\n";
constexpr size_t kSignatureSize = 8;
constexpr size_t kHeaderEnd = kSignatureSize + 4 + 4 + 13 + 4;  // length, "IHDR", data, CRC

// The CRC-32 of PNG chunks (ISO 3309, polynomial 0xEDB88320) over the chunk's type and data.
std::uint32_t ChunkCrc(const std::string& bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> entries{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      entries[n] = c;
    }
    return entries;
  }();
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char byte : bytes) crc = table[(crc ^ byte) & 0xFF] ^ (crc >> 8);
  return crc ^ 0xFFFFFFFFu;
}

std::string BigEndian(std::uint32_t value) {
  return {static_cast<char>(value >> 24), static_cast<char>(value >> 16),
          static_cast<char>(value >> 8), static_cast<char>(value)};
}

std::uint32_t ReadBigEndian(const std::string& bytes, size_t at) {
  std::uint32_t value = 0;
  for (size_t k = 0; k < 4; ++k) value = value << 8 | static_cast<unsigned char>(bytes[at + k]);
  return value;
}

bool IsPng(const std::string& png) {
  return png.size() >= kHeaderEnd && png.compare(0, kSignatureSize, kSignature) == 0 &&
         png.compare(kSignatureSize + 4, 4, "IHDR") == 0;
}

}  // namespace

std::string PngWithText(const std::string& png, const std::string& keyword,
                        const std::string& text) {
  if (!IsPng(png)) return png;
  const std::string body = "tEXt" + keyword + std::string(1, '\0') + text;
  const std::string chunk =
      BigEndian(static_cast<std::uint32_t>(body.size() - 4)) + body + BigEndian(ChunkCrc(body));
  return png.substr(0, kHeaderEnd) + chunk + png.substr(kHeaderEnd);
}

std::string PngWithDrapeVersion(const std::string& png) {
  return PngWithText(png, "Software", "drape " + DrapeVersion());
}

void AddDrapeVersionToPngFile(const std::filesystem::path& path) {
  const std::string png = ReadWholeFile(path);
  if (!IsPng(png)) return;
  WriteAtomically(path, [&png](std::ostream& out) { out << PngWithDrapeVersion(png); });
}

std::map<std::string, std::string> PngTexts(const std::string& png) {
  std::map<std::string, std::string> texts;
  if (!IsPng(png)) return texts;
  for (size_t at = kSignatureSize; at + 12 <= png.size();) {
    const std::uint32_t length = ReadBigEndian(png, at);
    if (at + 12 + length > png.size()) break;
    if (png.compare(at + 4, 4, "tEXt") == 0) {
      const std::string data = png.substr(at + 8, length);
      const size_t nul = data.find('\0');
      if (nul != std::string::npos) texts[data.substr(0, nul)] = data.substr(nul + 1);
    }
    at += 12 + length;
  }
  return texts;
}

}  // namespace drape
