#include "io/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/line_reader.h"

namespace haloplot::host {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

uint32_t u32_le(const std::string& b, size_t at) {
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 |
         uint32_t(uint8_t(b[at + 2])) << 16 | uint32_t(uint8_t(b[at + 3])) << 24;
}

float f32_le(const std::string& b, size_t at) {
  const uint32_t u = u32_le(b, at);
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

// What the bytes are, whatever the file is called.
enum class Content { kPly, kStlBinary, kStlAscii, kText, kBinary };

// A binary STL's size is exactly 84 + 50 n bytes, n the count at byte 80. `b` holds the
// file's first bytes (at least 84 of them where it has them), `size` is the whole file's.
bool binary_stl_size(const std::string& b, size_t size) {
  return size >= 84 && (size - 84) % 50 == 0 && (size - 84) / 50 == u32_le(b, 80);
}

std::string first_word(const std::string& b) {
  size_t i = b.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (i < b.size() && std::isspace(static_cast<unsigned char>(b[i]))) ++i;
  size_t j = i;
  while (j < b.size() && j < i + 16 && !std::isspace(static_cast<unsigned char>(b[j]))) ++j;
  return lower(b.substr(i, j - i));
}

// Whether first_word() reads no byte past the `head` of a longer file: the head alone then
// decides what the file is.
bool head_decides(const std::string& head) {
  size_t i = head.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  return i + 16 <= head.size();
}

// `b`: the file's bytes, or its first ones where head_decides(b); `size`: the whole file's.
Content sniff(const std::string& b, size_t size) {
  if (b.compare(0, 4, "ply\n") == 0 || b.compare(0, 5, "ply\r\n") == 0) return Content::kPly;
  if (binary_stl_size(b, size)) return Content::kStlBinary;
  const bool text = std::find(b.begin(), b.begin() + long(std::min<size_t>(b.size(), 1024)),
                              '\0') == b.begin() + long(std::min<size_t>(b.size(), 1024));
  if (!text) return Content::kBinary;
  return first_word(b) == "solid" ? Content::kStlAscii : Content::kText;
}

const char* content_name(Content c) {
  switch (c) {
    case Content::kPly:
      return "a PLY file";
    case Content::kStlBinary:
      return "a binary STL file";
    case Content::kStlAscii:
      return "an ASCII STL file";
    case Content::kText:
      return "text";
    case Content::kBinary:
      return "binary data";
  }
  return "";
}

// The refusal of a file whose content is not its extension's format; "" when it is.
std::string content_mismatch(MeshFormat f, const std::string& b, size_t size) {
  const Content c = sniff(b, size);
  const std::string is = std::string("it is ") + content_name(c);
  if (f == MeshFormat::kPly && c != Content::kPly)
    return "not a PLY file (it does not begin with a 'ply' line): " + is;
  // Other binary content named .obj is left to the OBJ reader, which names UTF-16 and NUL bytes.
  if (f == MeshFormat::kObj &&
      (c == Content::kPly || c == Content::kStlBinary || c == Content::kStlAscii))
    return "not a Wavefront OBJ file: " + is;
  if (f == MeshFormat::kStl && c == Content::kPly) return "not an STL file: " + is;
  if (f == MeshFormat::kStl && c == Content::kText)
    return "not an STL file: text that does not begin with 'solid' (first word '" +
           excerpt(first_word(b)) + "')";
  return "";
}

bool parse_coordinate(const std::string& s, double* out) {
  char* end = nullptr;
  *out = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && std::isfinite(*out);
}

// The whole stream, sized from its length when it can seek (a pipe cannot), read in blocks (a
// byte at a time through an iterator was slow on big files).
void read_all(std::istream& in, std::string* bytes) {
  const std::streampos start = in.tellg();
  if (start != std::streampos(-1) && in.seekg(0, std::ios::end)) {
    const std::streampos end = in.tellg();
    in.seekg(start);
    if (end != std::streampos(-1) && end > start && in) {
      // Straight into the string; whatever the size said, the reading below takes the rest.
      bytes->resize(size_t(end - start));
      in.read(&(*bytes)[0], std::streamsize(bytes->size()));
      bytes->resize(size_t(in.gcount()));
    }
  }
  if (!in.bad()) in.clear();  // a seek a pipe refused, or the end met: read on
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) bytes->append(chunk, size_t(in.gcount()));
}

// The first kHead bytes of a seekable file longer than that, when they decide its content
// (head_decides); false otherwise, with nothing read (the caller then reads it whole).
constexpr size_t kHead = size_t{64} << 10;
bool read_head(std::istream& in, std::string* head, size_t* size) {
  const std::streampos start = in.tellg();
  if (start != std::streampos(0) || !in.seekg(0, std::ios::end)) {
    in.clear();
    return false;  // a pipe: read it whole
  }
  const std::streampos end = in.tellg();
  in.seekg(0);
  if (end == std::streampos(-1) || size_t(end) <= kHead || !in) {
    in.clear();
    in.seekg(0);
    return false;
  }
  *size = size_t(end);
  head->resize(kHead);
  in.read(&(*head)[0], std::streamsize(kHead));
  const bool decided = size_t(in.gcount()) == kHead && head_decides(*head);
  in.clear();
  in.seekg(0);
  return decided && in.good();
}

// A stream reading the bytes in place (an istringstream would copy them).
struct ViewBuffer : std::streambuf {
  explicit ViewBuffer(const std::string& b) {
    char* p = const_cast<char*>(b.data());  // only read: the get area is never written
    setg(p, p, p + b.size());
  }
};

InputError read_binary_stl(const std::string& b, const std::string& name, ObjModel* out) {
  if (b.size() < 84)  // binary: no 'solid' first, or a NUL byte (many exporters write
                      // 'solid' into a binary header)
    return {name, 0,
            "byte " + std::to_string(b.size()) +
                ": the file ends inside the 84-byte header of a binary STL (" +
                (b.compare(0, 5, "solid") == 0
                     ? "it begins with 'solid' but holds a NUL byte, which text does not"
                     : "it does not begin with 'solid'") +
                ")"};
  const uint64_t n = u32_le(b, 80);
  if (b.size() != 84 + 50 * n)
    return {name, 0,
            "byte 80: the header counts " + std::to_string(n) + " triangles, 84 + 50 x " +
                std::to_string(n) + " = " + std::to_string(84 + 50 * n) +
                " bytes, but the file has " + std::to_string(b.size())};
  if (n == 0) return {name, 0, "byte 80: no triangles"};
  std::vector<double> xyz;
  xyz.reserve(size_t(9 * n));
  for (uint64_t t = 0; t < n; ++t) {
    const size_t at = size_t(84 + 50 * t + 12);  // past the normal
    for (size_t k = 0; k < 9; ++k) {
      const float c = f32_le(b, at + 4 * k);
      if (!std::isfinite(c))
        return {name, 0,
                "byte " + std::to_string(at + 4 * k) + ": a coordinate of triangle " +
                    std::to_string(t + 1) + " is not a finite number"};
      xyz.push_back(double(c));
    }
    const uint32_t v = uint32_t(3 * t);
    out->faces.push_back({v, v + 1, v + 2});
    out->face_lines.push_back(0);
  }
  CoordinateRounding rounding;
  rounding.note_binary(23);
  place_vertices(xyz, rounding, out);
  edges_from_faces(out);
  return {};
}

// One line of an ASCII STL; `corners` gathers the current facet's vertices.
struct AsciiStl {
  std::vector<double> xyz;
  std::vector<uint32_t> corners;
  CoordinateRounding rounding;
  bool in_facet = false;
  int facet_line = 0;

  std::string line(const std::vector<std::string>& f, int at, ObjModel* out) {
    const std::string k = lower(f[0]);
    if (k == "solid" || k == "endsolid" || k == "outer" || k == "endloop") {
      if (in_facet && (k == "solid" || k == "endsolid")) return "'" + k + "' inside a facet";
      return "";
    }
    if (k == "facet") {
      if (in_facet) return "a facet begins inside a facet (no 'endfacet' before it)";
      in_facet = true;
      facet_line = at;
      corners.clear();
      return "";
    }
    if (k == "vertex") {
      if (!in_facet) return "a vertex outside a facet";
      if (f.size() != 4) return "a vertex needs x y z";
      for (int i = 1; i <= 3; ++i) {
        double c;
        if (!parse_coordinate(f[size_t(i)], &c))
          return "coordinate '" + excerpt(f[size_t(i)]) + "' is not a number";
        xyz.push_back(c);
        rounding.note_text(f[size_t(i)]);
      }
      corners.push_back(uint32_t(xyz.size() / 3 - 1));
      return "";
    }
    if (k == "endfacet") {
      if (!in_facet) return "'endfacet' outside a facet";
      if (corners.size() < 3)
        return "a facet needs 3 vertices, found " + std::to_string(corners.size());
      out->faces.push_back(corners);
      out->face_lines.push_back(uint32_t(facet_line));
      in_facet = false;
      return "";
    }
    return "'" + excerpt(f[0]) +
           "' is not an STL keyword (solid, facet, outer loop, vertex, endloop, endfacet, "
           "endsolid)";
  }
};

InputError read_ascii_stl(const std::string& b, const std::string& name, ObjModel* out) {
  std::istringstream in(b);
  LineReader reader(in);
  std::vector<std::string> f;
  AsciiStl stl;
  while (reader.next(&f)) {
    const std::string why = stl.line(f, reader.line(), out);
    if (!why.empty()) return {name, reader.line(), why};
  }
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (stl.in_facet) return {name, reader.line(), "the file ends inside a facet"};
  if (out->faces.empty()) return {name, reader.line(), "no facets"};
  place_vertices(stl.xyz, stl.rounding, out);
  edges_from_faces(out);
  return {};
}

}  // namespace

bool mesh_format_of(const std::string& path, MeshFormat* format) {
  const size_t dot = path.rfind('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return false;
  const std::string ext = lower(path.substr(dot));
  if (ext == ".obj")
    *format = MeshFormat::kObj;
  else if (ext == ".stl")
    *format = MeshFormat::kStl;
  else if (ext == ".ply")
    *format = MeshFormat::kPly;
  else
    return false;
  return true;
}

InputError read_stl(const std::string& bytes, const std::string& name, ObjModel* out) {
  *out = ObjModel{};
  const Content c = sniff(bytes, bytes.size());
  if (c == Content::kStlAscii || c == Content::kText) return read_ascii_stl(bytes, name, out);
  return read_binary_stl(bytes, name, out);
}

InputError read_mesh_file(const std::string& path, ObjModel* out) {
  MeshFormat format = MeshFormat::kObj;
  if (!mesh_format_of(path, &format))
    return {path, 0, "not a model file: the name must end in .obj, .stl or .ply"};
  std::ifstream in(path, std::ios::binary);
  if (const InputError e = open_problem(path, in); e.failed()) return e;
  // An OBJ file is parsed from the file itself, its text never held whole: a 1.1M-triangle
  // Blender export's is 90 MB (normals and texture coordinates), held beside the model being
  // read, and the heap the reading reached is what the steps after it start from (15 MB of
  // that plot's 223 MB peak). Its first bytes and size say what it is, as the whole text did.
  std::string head;
  size_t size = 0;
  if (format == MeshFormat::kObj && read_head(in, &head, &size)) {
    const std::string mismatch = content_mismatch(format, head, size);
    if (!mismatch.empty()) return {path, 0, mismatch};
    head = std::string();
    return read_obj(in, path, out);
  }
  std::string bytes;
  read_all(in, &bytes);
  if (in.bad()) return {path, 0, "read error"};
  const std::string mismatch = content_mismatch(format, bytes, bytes.size());
  if (!mismatch.empty()) return {path, 0, mismatch};
  if (format == MeshFormat::kStl) return read_stl(bytes, path, out);
  if (format == MeshFormat::kPly) return read_ply(bytes, path, out);
  ViewBuffer view(bytes);
  std::istream text(&view);
  return read_obj(text, path, out);
}

}  // namespace haloplot::host
