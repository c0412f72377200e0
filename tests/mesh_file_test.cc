// The mesh-file reader (src/scene/mesh_file.h): one sheet written as OBJ, ASCII PLY, binary PLY
// (both byte orders, several value types) and STL (ASCII and binary), by hand here and by Python's
// meshio where it is installed, reads back as the same vertices and triangles, and builds the
// same mesh; truncated and garbage files are refused with the file and the line or byte offset.
#include "src/scene/mesh_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "src/model/mesh.h"
#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// A 3 × 3-node sheet, slightly bent (every coordinate exact in float32, as binary STL stores
// them), as triangles; vertices numbered in order of first appearance in the triangle list, as
// an STL's merged vertices are.
struct Sheet {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

Sheet MakeSheet() {
  auto point = [](int i, int j) {
    return Eigen::Vector3d(0.25 * i, 0.125 * j, i == 1 && j == 1 ? -0.0625 : 0.5);
  };
  Sheet sheet;
  std::map<std::array<int, 2>, int> id;
  auto vertex = [&](int i, int j) {
    const auto found = id.emplace(std::array<int, 2>{i, j}, static_cast<int>(id.size()));
    if (found.second) sheet.vertices.push_back(point(i, j));
    return found.first->second;
  };
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      const int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1);
      const int d = vertex(i, j + 1);
      sheet.triangles.push_back({a, b, c});
      sheet.triangles.push_back({a, c, d});
    }
  }
  return sheet;
}

std::string Obj(const Sheet& sheet) {
  std::ostringstream out;
  out << "# a sheet\no sheet\n";
  for (const auto& v : sheet.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  out << "vn 0 0 1\n";
  for (const auto& t : sheet.triangles) {
    out << "f " << t[0] + 1 << "//1 " << t[1] + 1 << "//1 " << t[2] + 1 << "//1\n";
  }
  return out.str();
}

std::string PlyHeader(const Sheet& sheet, const std::string& format, const std::string& coordinate,
                      const std::string& list) {
  std::ostringstream out;
  out << "ply\nformat " << format << " 1.0\ncomment written by mesh_file_test\nelement vertex "
      << sheet.vertices.size() << "\nproperty " << coordinate << " x\nproperty " << coordinate
      << " y\nproperty " << coordinate << " z\nproperty uchar red\nelement edge 1\n"
      << "property int vertex1\nproperty int vertex2\nelement face " << sheet.triangles.size()
      << "\nproperty " << list << " vertex_indices\nproperty short flags\nend_header\n";
  return out.str();
}

std::string AsciiPly(const Sheet& sheet) {
  std::ostringstream out;
  out << PlyHeader(sheet, "ascii", "float", "list uchar int");
  for (const auto& v : sheet.vertices) out << v.x() << ' ' << v.y() << ' ' << v.z() << " 255\n";
  out << "0 1\n";
  for (const auto& t : sheet.triangles)
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << " -7\n";
  return out.str();
}

// `value`'s `size` bytes in little- or big-endian order.
template <typename T>
void Append(T value, bool big_endian, std::string* out) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const std::uint16_t one = 1;
  char first = 0;
  std::memcpy(&first, &one, 1);
  const bool host_big = first == 0;
  if (big_endian != host_big) std::reverse(bytes, bytes + sizeof(T));
  out->append(bytes, sizeof(T));
}

// Little-endian floats and a uchar/int list, or big-endian doubles and an int/uint list.
std::string BinaryPly(const Sheet& sheet, bool big_endian) {
  std::string out =
      PlyHeader(sheet, big_endian ? "binary_big_endian" : "binary_little_endian",
                big_endian ? "double" : "float", big_endian ? "list int uint" : "list uchar int");
  for (const auto& v : sheet.vertices) {
    for (int c = 0; c < 3; ++c) {
      if (big_endian) {
        Append<double>(v[c], true, &out);
      } else {
        Append<float>(static_cast<float>(v[c]), false, &out);
      }
    }
    Append<std::uint8_t>(255, big_endian, &out);
  }
  Append<std::int32_t>(0, big_endian, &out);
  Append<std::int32_t>(1, big_endian, &out);
  for (const auto& t : sheet.triangles) {
    if (big_endian) {
      Append<std::int32_t>(3, true, &out);
      for (int v : t) Append<std::uint32_t>(v, true, &out);
    } else {
      Append<std::uint8_t>(3, false, &out);
      for (int v : t) Append<std::int32_t>(v, false, &out);
    }
    Append<std::int16_t>(-7, big_endian, &out);
  }
  return out;
}

std::string AsciiStl(const Sheet& sheet) {
  std::ostringstream out;
  out << "solid sheet\n";
  for (const auto& t : sheet.triangles) {
    out << "  facet normal 0 0 1\n    outer loop\n";
    for (int v : t) {
      const auto& p = sheet.vertices[v];
      out << "      vertex " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid sheet\n";
  return out.str();
}

std::string BinaryStl(const Sheet& sheet) {
  std::string out(80, ' ');
  out.replace(0, 5, "solid");  // a binary header may start with "solid": its size tells
  Append<std::uint32_t>(sheet.triangles.size(), false, &out);
  for (const auto& t : sheet.triangles) {
    for (int c = 0; c < 3; ++c) Append<float>(c == 2 ? 1.0f : 0.0f, false, &out);
    for (int v : t) {
      for (int c = 0; c < 3; ++c)
        Append<float>(static_cast<float>(sheet.vertices[v][c]), false, &out);
    }
    Append<std::uint16_t>(0, false, &out);
  }
  return out;
}

class MeshFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.emplace("mesh_file_test");
    folder_ = scratch_->path();
  }
  void TearDown() override { scratch_.reset(); }

  std::string Write(const std::string& name, const std::string& bytes) const {
    const std::string path = (folder_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  // The message of the MeshFileError reading `bytes` as `name` throws ("" if none).
  std::string ErrorOf(const std::string& name, const std::string& bytes) const {
    try {
      ReadMeshFile(Write(name, bytes));
    } catch (const MeshFileError& error) {
      return error.what();
    }
    return "";
  }

  std::optional<testing::ScratchFolder> scratch_;
  fs::path folder_;
};

void ExpectSheet(const MeshFileData& data, const Sheet& sheet, const std::string& name) {
  ASSERT_EQ(data.vertices.size(), sheet.vertices.size()) << name;
  for (size_t v = 0; v < sheet.vertices.size(); ++v) {
    EXPECT_EQ(data.vertices[v], sheet.vertices[v]) << name << " vertex " << v;
  }
  ASSERT_EQ(data.faces.size(), sheet.triangles.size()) << name;
  ASSERT_EQ(data.face_places.size(), data.faces.size()) << name;
  for (size_t f = 0; f < sheet.triangles.size(); ++f) {
    const auto& t = sheet.triangles[f];
    EXPECT_EQ(data.faces[f], (std::vector<int>{t[0], t[1], t[2]})) << name << " face " << f;
  }
}

TEST_F(MeshFileTest, TheSameSheetFromEveryFormat) {
  const Sheet sheet = MakeSheet();
  ASSERT_EQ(sheet.vertices.size(), 9u);
  const std::map<std::string, std::string> files = {{"sheet.obj", Obj(sheet)},
                                                    {"sheet_ascii.ply", AsciiPly(sheet)},
                                                    {"sheet_little.ply", BinaryPly(sheet, false)},
                                                    {"sheet_big.PLY", BinaryPly(sheet, true)},
                                                    {"sheet_ascii.stl", AsciiStl(sheet)},
                                                    {"sheet_binary.stl", BinaryStl(sheet)}};
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kFile;
  spec.where = Location{"scene.yaml", 3, 5, "mesh"};
  spec.path = Write("reference.obj", Obj(sheet));
  const Mesh reference = BuildMesh(spec);
  for (const auto& [name, bytes] : files) {
    const std::string path = Write(name, bytes);
    ExpectSheet(ReadMeshFile(path), sheet, name);
    spec.path = path;
    const Mesh mesh = BuildMesh(spec);
    EXPECT_EQ(mesh.nodes, reference.nodes) << name;
    EXPECT_EQ(mesh.triangles, reference.triangles) << name;
    EXPECT_EQ(mesh.warp, reference.warp) << name;
    EXPECT_EQ(mesh.area, reference.area) << name;
  }
  // Each STL triangle repeats its corners; merged, the sheet's 8 triangles share 9 vertices.
  EXPECT_EQ(ReadMeshFile(Write("again.stl", BinaryStl(sheet))).vertices.size(), 9u);
}

TEST_F(MeshFileTest, TextErrorsNameTheLine) {
  const Sheet sheet = MakeSheet();
  std::string garbage = AsciiPly(sheet);
  garbage.replace(garbage.find("0.25 0 0.5"), 4, "0.2x");  // the second vertex, line 17
  EXPECT_NE(ErrorOf("garbage.ply", garbage).find("garbage.ply:17: expected a number in the vertex"),
            std::string::npos)
      << ErrorOf("garbage.ply", garbage);
  const std::string ascii = AsciiPly(sheet);
  const std::string truncated = ascii.substr(0, ascii.size() - 12);
  EXPECT_NE(ErrorOf("truncated.ply", truncated).find("face data ends early"), std::string::npos)
      << ErrorOf("truncated.ply", truncated);
  EXPECT_NE(ErrorOf("header.ply", "ply\nformat ascii 1.0\nelement vertex 1\n")
                .find("header.ply:4: the header has no end_header line"),
            std::string::npos);
  EXPECT_NE(ErrorOf("type.ply",
                    "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n"
                    "end_header\n")
                .find("type.ply:4: unknown type 'quad'"),
            std::string::npos);
  EXPECT_NE(ErrorOf("no_z.ply",
                    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                    "property float y\nend_header\n0 0\n")
                .find("no_z.ply:3: the vertex element has no scalar property z"),
            std::string::npos);
  std::string stl = AsciiStl(sheet);
  stl.erase(stl.find("      vertex"), stl.find('\n', stl.find("      vertex")) + 1 -
                                          stl.find("      vertex"));  // 2 corners, 1st facet
  EXPECT_NE(ErrorOf("two.stl", stl).find("two.stl:6: a facet needs exactly 3 vertices"),
            std::string::npos)
      << ErrorOf("two.stl", stl);
  EXPECT_NE(ErrorOf("nan.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 nan 0\n")
                .find("nan.stl:4: a vertex needs three finite coordinates"),
            std::string::npos);
  EXPECT_NE(ErrorOf("open.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n")
                .find("open.stl:2: the file ends inside this facet"),
            std::string::npos);
  EXPECT_NE(ErrorOf("bad.obj", "v 0 0 0\nv 1 0\n").find("bad.obj:2: a vertex"), std::string::npos);
  EXPECT_NE(ErrorOf("sheet.off", "OFF\n").find("unknown mesh file format"), std::string::npos);
  EXPECT_NE(ErrorOf("empty.stl", "").find("empty.stl: byte 0: the file ends inside the 84-byte"),
            std::string::npos);
  fs::create_directories(folder_ / "folder.ply");
  try {
    ReadMeshFile((folder_ / "folder.ply").string());
    ADD_FAILURE() << "a folder was read";
  } catch (const MeshFileError& error) {
    EXPECT_NE(std::string(error.what()).find("not a regular file"), std::string::npos);
  }
}

TEST_F(MeshFileTest, BinaryErrorsNameTheByte) {
  const Sheet sheet = MakeSheet();
  const std::string ply = BinaryPly(sheet, false);
  const size_t body = ply.find("end_header\n") + 11;
  // Cut inside the third vertex (13 bytes a vertex): the read fails at the cut.
  const size_t cut = body + 2 * 13 + 6;
  const std::string message = ErrorOf("cut.ply", ply.substr(0, cut));
  EXPECT_NE(
      message.find("cut.ply: byte " + std::to_string(cut - 2) + ": the vertex data ends early"),
      std::string::npos)
      << message;
  // A face list announcing 200 vertices, more than the bytes left.
  std::string long_list = ply;
  const size_t first_face = body + 9 * 13 + 8;
  long_list[first_face] = static_cast<char>(200);
  const std::string bad_length = ErrorOf("long.ply", long_list);
  EXPECT_NE(bad_length.find("long.ply: byte " + std::to_string(first_face)), std::string::npos)
      << bad_length;
  EXPECT_NE(bad_length.find("bad length"), std::string::npos) << bad_length;

  const std::string stl = BinaryStl(sheet);
  const std::string short_stl = ErrorOf("short.stl", stl.substr(0, stl.size() - 1));
  EXPECT_NE(short_stl.find("short.stl: byte 80: the header announces 8 triangles (484 bytes)"),
            std::string::npos)
      << short_stl;
  EXPECT_NE(ErrorOf("tiny.stl", std::string(10, '\0')).find("tiny.stl: byte 10"),
            std::string::npos);
  std::string nan_stl = stl;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan_stl[84 + 50 + 12 + 4], &nan, 4);  // the second triangle's first vertex, y
  EXPECT_NE(ErrorOf("nan.stl", nan_stl).find("nan.stl: byte 146: a vertex has a non-finite"),
            std::string::npos)
      << ErrorOf("nan.stl", nan_stl);
}

// Through BuildMesh the error is located at the scene's mesh key, then in the file.
TEST_F(MeshFileTest, BuildMeshLocatesFileErrorsInTheScene) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kFile;
  spec.where = Location{"scene.yaml", 3, 5, "mesh"};
  const Sheet sheet = MakeSheet();
  std::string stl = BinaryStl(sheet);
  // The first triangle's third corner = its first: a face that uses a vertex twice.
  stl.replace(84 + 12 + 24, 12, stl.substr(84 + 12, 12));
  spec.path = Write("degenerate.stl", stl);
  try {
    BuildMesh(spec);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("scene.yaml:3:5: mesh: ", 0), 0u) << message;
    EXPECT_NE(message.find("degenerate.stl: byte 84: a face uses vertex 1 twice"),
              std::string::npos)
        << message;
  }
}

// Runs /usr/bin/python3 (Debian's, with its packages) on `script`; true when it exited 0.
bool RunPython(const fs::path& folder, const std::string& script) {
  const fs::path file = folder / "write.py";
  std::ofstream(file) << script;
  return std::system(
             ("/usr/bin/python3 " + file.string() + " > " + (folder / "log").string() + " 2>&1")
                 .c_str()) == 0;
}

// meshio (what Python users write meshes with) writes binary PLY and both STLs; drape reads them.
TEST_F(MeshFileTest, MeshioFilesReadBack) {
  if (std::system("/usr/bin/python3 -c 'import meshio' 2>/dev/null") != 0) {
    GTEST_SKIP() << "python3-meshio is not installed";
  }
  const Sheet sheet = MakeSheet();
  std::ostringstream script;
  script << "import meshio, numpy\npoints = numpy.array([";
  for (const auto& v : sheet.vertices)
    script << '[' << v.x() << ',' << v.y() << ',' << v.z() << "],";
  script << "])\ncells = [('triangle', numpy.array([";
  for (const auto& t : sheet.triangles) script << '[' << t[0] << ',' << t[1] << ',' << t[2] << "],";
  script << "]))]\nmesh = meshio.Mesh(points, cells)\n"
         << "meshio.write('" << (folder_ / "binary.ply").string() << "', mesh, binary=True)\n"
         << "meshio.write('" << (folder_ / "ascii.ply").string() << "', mesh, binary=False)\n"
         << "meshio.write('" << (folder_ / "binary.stl").string() << "', mesh, binary=True)\n"
         << "meshio.write('" << (folder_ / "ascii.stl").string() << "', mesh, binary=False)\n";
  ASSERT_TRUE(RunPython(folder_, script.str())) << std::ifstream(folder_ / "log").rdbuf();
  for (const char* name : {"binary.ply", "ascii.ply", "binary.stl", "ascii.stl"}) {
    ExpectSheet(ReadMeshFile((folder_ / name).string()), sheet, name);
  }
}

}  // namespace
}  // namespace drape
