// The mesh-file reader (see mesh_file.h). The whole file is read into memory once; text formats
// are read token by token with their line numbers, binary ones value by value with their byte
// offsets, and every count is checked against what is left of the file before it is trusted.
//
// Formats: OBJ (Wavefront); PLY (Greg Turk's polygon file format, 1994: a text header, then the
// elements in header order, as text or packed binary values of the declared sizes); STL (3D
// Systems' stereolithography format: ASCII `solid … facet normal … outer loop vertex ×3 endloop
// endfacet … endsolid`, or binary: an 80-byte header, a little-endian uint32 triangle count,
// then per triangle 12 little-endian float32 — normal and three vertices — and a uint16).
#include "src/scene/mesh_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "src/scene/number_text.h"

namespace drape {

std::string PlaceText(const std::string& path, const FilePlace& place) {
  if (place.line > 0) return path + ":" + std::to_string(place.line);
  if (place.byte >= 0) return path + ": byte " + std::to_string(place.byte);
  return path;
}

namespace {

[[noreturn]] void Fail(const std::string& path, const FilePlace& place, const std::string& what) {
  throw MeshFileError(PlaceText(path, place) + ": " + what);
}

FilePlace Line(int line) { return FilePlace{line, -1}; }
FilePlace Byte(size_t byte) { return FilePlace{0, static_cast<long long>(byte)}; }

std::string Lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string ReadBytes(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    Fail(path, {}, "cannot read the mesh file: not a regular file (a folder, a device or missing)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) Fail(path, {}, "cannot read the mesh file");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A whole token as a number (strtod's syntax), or false.
bool ParseNumber(const std::string& token, double* value) {
  const auto number = WholeNumber(token);
  if (number) *value = *number;
  return number.has_value();
}

// A value that must be a whole number in int's range (a count or a vertex index).
bool AsInt(double value, int* result) {
  if (!(std::abs(value) <= 2147483647.0) || value != std::floor(value)) return false;
  *result = static_cast<int>(value);
  return true;
}

// Whitespace-separated tokens of a text, with the line each one is on.
class TextCursor {
 public:
  TextCursor(const std::string& text, size_t start, int first_line)
      : text_(text), at_(start), line_(first_line) {}

  // The next token, or false at the end of the text; line() is then the token's line.
  bool Next(std::string* token) {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
    if (at_ >= text_.size()) return false;
    const size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    token->assign(text_, start, at_ - start);
    return true;
  }
  // Skips to the end of the current line.
  void SkipLine() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }
  int line() const { return line_; }

 private:
  const std::string& text_;
  size_t at_;
  int line_;
};

// A finite point of three text tokens.
Eigen::Vector3d ReadTextPoint(TextCursor* cursor, const std::string& path, const char* what) {
  Eigen::Vector3d p;
  for (int c = 0; c < 3; ++c) {
    std::string token;
    if (!cursor->Next(&token)) {
      Fail(path, Line(cursor->line()),
           std::string(what) + " needs three finite coordinates, found " + std::to_string(c));
    }
    if (!ParseNumber(token, &p[c]) || !std::isfinite(p[c])) {
      Fail(path, Line(cursor->line()),
           std::string(what) + " needs three finite coordinates, got '" + token + "'");
    }
  }
  return p;
}

// ------------------------------------------------------------------------------------- OBJ

// `v x y z` and `f a b c ...` lines (a may be `a/t/n`, `a//n`, or negative = relative); every
// other statement (vn, vt, o, g, s, usemtl, comments) is ignored.
MeshFileData ReadObj(const std::string& bytes, const std::string& path) {
  MeshFileData data;
  std::istringstream in(bytes);
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::istringstream fields(text);
    std::string keyword;
    if (!(fields >> keyword)) continue;
    if (keyword == "v") {
      std::string coordinates;
      std::getline(fields, coordinates);
      TextCursor cursor(coordinates, 0, line);
      data.vertices.push_back(ReadTextPoint(&cursor, path, "a vertex"));
    } else if (keyword == "f") {
      std::vector<int> face;
      std::string token;
      while (fields >> token) {
        double number = 0.0;
        int index = 0;
        if (!ParseNumber(token.substr(0, token.find('/')), &number) || !AsInt(number, &index) ||
            index == 0) {
          Fail(path, Line(line), "bad face vertex '" + token + "'");
        }
        face.push_back(index > 0 ? index - 1 : static_cast<int>(data.vertices.size()) + index);
      }
      data.faces.push_back(face);
      data.face_places.push_back(Line(line));
    }
  }
  return data;
}

// ------------------------------------------------------------------------------------- PLY

enum class PlyFormat { kAscii, kLittleEndian, kBigEndian };

struct PlyType {
  int size = 0;  // bytes in a binary file
  bool is_float = false, is_signed = false;
};

bool FindPlyType(const std::string& name, PlyType* type) {
  static const std::map<std::string, PlyType> types = {
      {"char", {1, false, true}},    {"int8", {1, false, true}},    {"uchar", {1, false, false}},
      {"uint8", {1, false, false}},  {"short", {2, false, true}},   {"int16", {2, false, true}},
      {"ushort", {2, false, false}}, {"uint16", {2, false, false}}, {"int", {4, false, true}},
      {"int32", {4, false, true}},   {"uint", {4, false, false}},   {"uint32", {4, false, false}},
      {"float", {4, true, true}},    {"float32", {4, true, true}},  {"double", {8, true, true}},
      {"float64", {8, true, true}}};
  const auto found = types.find(name);
  if (found == types.end()) return false;
  *type = found->second;
  return true;
}

struct PlyProperty {
  std::string name;
  PlyType type;  // the value's type (a list's items)
  bool list = false;
  PlyType count_type;  // a list's count
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;  // of its `element` statement
};

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  size_t body = 0;    // byte offset of the first byte after `end_header`'s line
  int body_line = 0;  // the line the body starts on (ASCII)
};

PlyProperty ReadPlyProperty(std::istringstream* fields, const std::string& path, int line) {
  PlyProperty property;
  std::string type;
  *fields >> type;
  if (type == "list") {
    std::string count_type, item_type;
    *fields >> count_type >> item_type;
    if (!FindPlyType(count_type, &property.count_type) || property.count_type.is_float) {
      Fail(path, Line(line),
           "a list's count type must be an integer type, got '" + count_type + "'");
    }
    type = item_type;
    property.list = true;
  }
  if (!FindPlyType(type, &property.type)) Fail(path, Line(line), "unknown type '" + type + "'");
  if (!(*fields >> property.name)) Fail(path, Line(line), "a property needs a name");
  return property;
}

void CheckVertexProperties(const PlyHeader& header, const std::string& path) {
  for (const auto& element : header.elements) {
    if (element.name != "vertex") continue;
    for (const char* axis : {"x", "y", "z"}) {
      const bool found =
          std::any_of(element.properties.begin(), element.properties.end(),
                      [&](const PlyProperty& p) { return p.name == axis && !p.list; });
      if (!found) {
        Fail(path, Line(element.line),
             std::string("the vertex element has no scalar property ") + axis);
      }
    }
    return;
  }
  Fail(path, {}, "the header has no vertex element");
}

PlyHeader ReadPlyHeader(const std::string& bytes, const std::string& path) {
  PlyHeader header;
  size_t at = 0;
  bool has_format = false;
  for (int line = 1;; ++line) {
    const size_t end = bytes.find('\n', at);
    if (end == std::string::npos) Fail(path, Line(line), "the header has no end_header line");
    std::string text = bytes.substr(at, end - at);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    at = end + 1;
    std::istringstream fields(text);
    std::string keyword;
    fields >> keyword;
    if (line == 1) {
      if (keyword != "ply") Fail(path, Line(1), "not a PLY file (its first line is not 'ply')");
    } else if (keyword == "format") {
      std::string format;
      fields >> format;
      static const std::map<std::string, PlyFormat> formats = {
          {"ascii", PlyFormat::kAscii},
          {"binary_little_endian", PlyFormat::kLittleEndian},
          {"binary_big_endian", PlyFormat::kBigEndian}};
      const auto found = formats.find(format);
      if (found == formats.end()) Fail(path, Line(line), "unknown PLY format '" + format + "'");
      header.format = found->second;
      has_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      std::string count;
      fields >> element.name >> count;
      double value = 0.0;
      if (!ParseNumber(count, &value) || !(value >= 0.0 && value <= 9.0e15) ||
          value != std::floor(value)) {
        Fail(path, Line(line), "an element needs a name and a count (a whole number >= 0)");
      }
      element.count = static_cast<long long>(value);
      element.line = line;
      header.elements.push_back(element);
    } else if (keyword == "property") {
      if (header.elements.empty()) Fail(path, Line(line), "a property before any element");
      header.elements.back().properties.push_back(ReadPlyProperty(&fields, path, line));
    } else if (keyword == "end_header") {
      if (!has_format) Fail(path, Line(line), "the header has no format line");
      header.body = at;
      header.body_line = line + 1;
      CheckVertexProperties(header, path);
      return header;
    } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
      Fail(path, Line(line), "unknown header statement '" + keyword + "'");
    }
  }
}

// Reads the values of a PLY body, text or binary, and says where the next one is.
class PlyValues {
 public:
  PlyValues(const std::string& bytes, const PlyHeader& header, const std::string& path)
      : bytes_(bytes),
        format_(header.format),
        path_(path),
        text_(bytes, header.body, header.body_line),
        at_(header.body) {}

  FilePlace place() const { return format_ == PlyFormat::kAscii ? Line(text_.line()) : Byte(at_); }

  double Next(const PlyType& type, const std::string& what) {
    if (format_ == PlyFormat::kAscii) {
      std::string token;
      if (!text_.Next(&token)) Fail(path_, place(), "the " + what + " data ends early");
      double value = 0.0;
      if (!ParseNumber(token, &value)) {
        Fail(path_, place(), "expected a number in the " + what + " data, got '" + token + "'");
      }
      return value;
    }
    if (bytes_.size() - at_ < static_cast<size_t>(type.size)) {
      Fail(path_, place(), "the " + what + " data ends early");
    }
    const auto* raw = reinterpret_cast<const unsigned char*>(bytes_.data() + at_);
    at_ += type.size;
    return Decode(raw, type, format_ == PlyFormat::kBigEndian);
  }

  // Bytes left in a binary body (the text body's size for ASCII, an upper bound on its values).
  size_t left() const { return bytes_.size() - std::min(at_, bytes_.size()); }

 private:
  // The value of `type.size` bytes in the file's byte order: assembled as an unsigned integer,
  // then read as a two's-complement integer or as IEEE 754 bits.
  static double Decode(const unsigned char* raw, const PlyType& type, bool big_endian) {
    const int size = type.size;
    std::uint64_t bits = 0;
    for (int k = 0; k < size; ++k) {
      bits |= static_cast<std::uint64_t>(raw[k]) << (8 * (big_endian ? size - 1 - k : k));
    }
    if (type.is_float && size == 4) {
      const auto narrow = static_cast<std::uint32_t>(bits);
      float value = 0.0f;
      std::memcpy(&value, &narrow, 4);
      return value;
    }
    if (type.is_float) {
      double value = 0.0;
      std::memcpy(&value, &bits, 8);
      return value;
    }
    if (type.is_signed && ((bits >> (8 * size - 1)) & 1)) {
      return static_cast<double>(bits) - std::ldexp(1.0, 8 * size);
    }
    return static_cast<double>(bits);
  }

  const std::string& bytes_;
  PlyFormat format_;
  const std::string& path_;
  TextCursor text_;
  size_t at_;
};

// One list property's items: the vertex ids when `ids` is given, else skipped.
void ReadPlyList(const PlyProperty& property, const std::string& element, PlyValues* values,
                 const std::string& path, std::vector<int>* ids) {
  const FilePlace at = values->place();
  int count = 0;
  if (!AsInt(values->Next(property.count_type, element), &count) || count < 0 ||
      static_cast<size_t>(count) > values->left()) {
    Fail(path, at, "a list in the " + element + " data has a bad length");
  }
  for (int k = 0; k < count; ++k) {
    const FilePlace item = values->place();
    const double value = values->Next(property.type, element);
    int id = 0;
    if (ids && !AsInt(value, &id)) Fail(path, item, "a face's vertex index is not a whole number");
    if (ids) ids->push_back(id);
  }
}

MeshFileData ReadPly(const std::string& bytes, const std::string& path) {
  const PlyHeader header = ReadPlyHeader(bytes, path);
  PlyValues values(bytes, header, path);
  MeshFileData data;
  for (const PlyElement& element : header.elements) {
    if (element.properties.empty()) continue;  // rows of nothing take no room
    const bool vertex = element.name == "vertex", face = element.name == "face";
    for (long long row = 0; row < element.count; ++row) {
      const FilePlace start = values.place();
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      std::vector<int> ids;
      bool first_list = true;
      for (const PlyProperty& property : element.properties) {
        if (property.list) {
          ReadPlyList(property, element.name, &values, path, face && first_list ? &ids : nullptr);
          first_list = false;
          continue;
        }
        const double value = values.Next(property.type, element.name);
        if (vertex && property.name.size() == 1 && property.name[0] >= 'x' &&
            property.name[0] <= 'z') {
          p[property.name[0] - 'x'] = value;
        }
      }
      if (vertex) {
        if (!p.allFinite()) Fail(path, start, "a vertex has a non-finite coordinate");
        data.vertices.push_back(p);
      } else if (face) {
        data.faces.push_back(ids);
        data.face_places.push_back(start);
      }
    }
  }
  return data;
}

// ------------------------------------------------------------------------------------- STL

// Triangles as read (three points each) and where each is, before the vertices are merged.
struct StlTriangles {
  std::vector<std::array<Eigen::Vector3d, 3>> corners;
  std::vector<FilePlace> places;
};

// Exactly equal points become one vertex, numbered in order of first appearance.
MeshFileData MergeStlVertices(const StlTriangles& triangles) {
  MeshFileData data;
  std::map<std::array<double, 3>, int> ids;
  for (size_t t = 0; t < triangles.corners.size(); ++t) {
    std::vector<int> face;
    for (const Eigen::Vector3d& p : triangles.corners[t]) {
      const auto inserted =
          ids.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, static_cast<int>(ids.size()));
      if (inserted.second) data.vertices.push_back(p);
      face.push_back(inserted.first->second);
    }
    data.faces.push_back(face);
    data.face_places.push_back(triangles.places[t]);
  }
  return data;
}

// A binary STL announces n triangles and is 84 + 50 n bytes long.
bool IsBinaryStl(const std::string& bytes) {
  if (bytes.size() < 84) return false;
  std::uint32_t count = 0;
  for (int k = 0; k < 4; ++k)
    count |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[80 + k])) << (8 * k);
  return bytes.size() == 84 + 50 * static_cast<std::uint64_t>(count);
}

float LittleEndianFloat(const std::string& bytes, size_t at) {
  std::uint32_t bits = 0;
  for (int k = 0; k < 4; ++k) {
    bits |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
  }
  float value = 0.0f;
  std::memcpy(&value, &bits, 4);
  return value;
}

StlTriangles ReadBinaryStl(const std::string& bytes, const std::string& path) {
  if (bytes.size() < 84) {
    Fail(path, Byte(bytes.size()),
         "the file ends inside the 84-byte header of a binary STL (an ASCII STL starts with "
         "'solid')");
  }
  std::uint64_t count = 0;
  for (int k = 0; k < 4; ++k) {
    count |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[80 + k])) << (8 * k);
  }
  if (bytes.size() != 84 + 50 * count) {
    Fail(path, Byte(80),
         "the header announces " + std::to_string(count) + " triangles (" +
             std::to_string(84 + 50 * count) + " bytes), the file has " +
             std::to_string(bytes.size()) + " bytes");
  }
  StlTriangles triangles;
  for (std::uint64_t t = 0; t < count; ++t) {
    const size_t at = 84 + 50 * t;
    std::array<Eigen::Vector3d, 3> corners;
    for (int v = 0; v < 3; ++v) {
      for (int c = 0; c < 3; ++c)
        corners[v][c] = LittleEndianFloat(bytes, at + 12 * (v + 1) + 4 * c);
      if (!corners[v].allFinite()) {
        Fail(path, Byte(at + 12 * (v + 1)), "a vertex has a non-finite coordinate");
      }
    }
    triangles.corners.push_back(corners);
    triangles.places.push_back(Byte(at));
  }
  return triangles;
}

StlTriangles ReadAsciiStl(const std::string& bytes, const std::string& path) {
  TextCursor cursor(bytes, 0, 1);
  StlTriangles triangles;
  std::vector<Eigen::Vector3d> loop;
  bool in_loop = false;
  int facet_line = 0;
  std::string token;
  while (cursor.Next(&token)) {
    if (token == "solid" || token == "endsolid") {
      cursor.SkipLine();  // the solid's name
    } else if (token == "facet") {
      facet_line = cursor.line();
    } else if (token == "normal") {
      ReadTextPoint(&cursor, path, "a facet normal");
    } else if (token == "outer") {
      if (!cursor.Next(&token) || token != "loop")
        Fail(path, Line(cursor.line()), "expected 'loop'");
      in_loop = true;
      loop.clear();
    } else if (token == "vertex") {
      if (!in_loop) Fail(path, Line(cursor.line()), "a vertex outside an 'outer loop'");
      loop.push_back(ReadTextPoint(&cursor, path, "a vertex"));
      if (loop.size() > 3) Fail(path, Line(cursor.line()), "a facet has more than 3 vertices");
    } else if (token == "endloop") {
      if (!in_loop || loop.size() != 3) {
        Fail(path, Line(cursor.line()), "a facet needs exactly 3 vertices");
      }
      triangles.corners.push_back({loop[0], loop[1], loop[2]});
      triangles.places.push_back(Line(facet_line > 0 ? facet_line : cursor.line()));
      in_loop = false;
    } else if (token != "endfacet") {
      Fail(path, Line(cursor.line()), "unexpected '" + token + "' in an ASCII STL");
    }
  }
  if (in_loop) Fail(path, Line(facet_line), "the file ends inside this facet");
  return triangles;
}

// An ASCII STL: `solid` and its name on the first line, then `facet` or `endsolid`. (A binary
// STL's free 80-byte header may start with "solid" too.)
bool IsAsciiStl(const std::string& bytes) {
  if (IsBinaryStl(bytes)) return false;
  TextCursor cursor(bytes, 0, 1);
  std::string token;
  if (!cursor.Next(&token) || token != "solid") return false;
  cursor.SkipLine();
  return cursor.Next(&token) && (token == "facet" || token == "endsolid");
}

MeshFileData ReadStl(const std::string& bytes, const std::string& path) {
  const bool ascii = IsAsciiStl(bytes);
  return MergeStlVertices(ascii ? ReadAsciiStl(bytes, path) : ReadBinaryStl(bytes, path));
}

}  // namespace

MeshFileData ReadMeshFile(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const std::string extension = dot == std::string::npos ? "" : Lowercase(path.substr(dot + 1));
  if (extension != "obj" && extension != "ply" && extension != "stl") {
    Fail(path, {}, "unknown mesh file format (use .obj, .ply or .stl)");
  }
  const std::string bytes = ReadBytes(path);
  if (extension == "obj") return ReadObj(bytes, path);
  if (extension == "ply") return ReadPly(bytes, path);
  return ReadStl(bytes, path);
}

}  // namespace drape
