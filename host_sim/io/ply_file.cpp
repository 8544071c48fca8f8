// The PLY reader (io/mesh_file.h): the header, then the elements' data in ASCII or binary.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "io/line_reader.h"
#include "io/mesh_file.h"

namespace haloplot::host {
namespace {

enum class Kind { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64 };
enum class Encoding { kAscii, kLittle, kBig };

bool kind_of(const std::string& s, Kind* k) {
  static const struct {
    const char* name;
    Kind kind;
  } kNames[] = {{"char", Kind::kI8},    {"int8", Kind::kI8},     {"uchar", Kind::kU8},
                {"uint8", Kind::kU8},   {"short", Kind::kI16},   {"int16", Kind::kI16},
                {"ushort", Kind::kU16}, {"uint16", Kind::kU16},  {"int", Kind::kI32},
                {"int32", Kind::kI32},  {"uint", Kind::kU32},    {"uint32", Kind::kU32},
                {"float", Kind::kF32},  {"float32", Kind::kF32}, {"double", Kind::kF64},
                {"float64", Kind::kF64}};
  for (const auto& n : kNames)
    if (s == n.name) {
      *k = n.kind;
      return true;
    }
  return false;
}

size_t size_of(Kind k) {
  switch (k) {
    case Kind::kI8:
    case Kind::kU8:
      return 1;
    case Kind::kI16:
    case Kind::kU16:
      return 2;
    case Kind::kI32:
    case Kind::kU32:
    case Kind::kF32:
      return 4;
    case Kind::kF64:
      return 8;
  }
  return 1;
}

struct Property {
  Kind kind = Kind::kF32;
  bool list = false;
  Kind count_kind = Kind::kU8;
  std::string name;
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> props;
};

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  size_t data_at = 0;  // the first byte after end_header's line
  int lines = 0;       // the header's lines
};

// One header line (split on blanks) into *h; "" or what is wrong.
std::string header_line(const std::vector<std::string>& f, Header* h) {
  const std::string& k = f[0];
  if (k == "format") {
    if (f.size() != 3 || f[2] != "1.0")
      return "the format line must be 'format ascii|binary_little_endian|binary_big_endian 1.0'";
    if (f[1] == "ascii")
      h->encoding = Encoding::kAscii;
    else if (f[1] == "binary_little_endian")
      h->encoding = Encoding::kLittle;
    else if (f[1] == "binary_big_endian")
      h->encoding = Encoding::kBig;
    else
      return "unknown format '" + excerpt(f[1]) + "'";
  } else if (k == "element") {
    int64_t n = 0;
    if (f.size() != 3 || !parse_int(f[2], 0, int64_t(1) << 32, &n))
      return "an element line must be 'element NAME COUNT'";
    h->elements.push_back(Element{f[1], uint64_t(n), {}});
  } else if (k == "property") {
    if (h->elements.empty()) return "a property before any element";
    Property p;
    const bool list = f.size() == 5 && f[1] == "list";
    if (list && (!kind_of(f[2], &p.count_kind) || !kind_of(f[3], &p.kind)))
      return "a list property must be 'property list COUNT_TYPE ITEM_TYPE NAME' (types char, "
             "uchar, short, ushort, int, uint, float, double or int8 ... float64)";
    if (!list && (f.size() != 3 || !kind_of(f[1], &p.kind)))
      return "a property must be 'property TYPE NAME' (types char, uchar, short, ushort, int, "
             "uint, float, double or int8 ... float64)";
    p.list = list;
    p.name = f.back();
    h->elements.back().props.push_back(p);
  }
  return "";  // comment, obj_info and other lines (some exporters write bare text) skipped
}

// The header from the file's start; on failure *line is where.
std::string read_header(const std::string& b, Header* h, int* line) {
  size_t at = 0;
  for (*line = 1;; ++*line) {
    const size_t end = b.find('\n', at);
    if (end == std::string::npos) return "the file ends in the header (no 'end_header' line)";
    std::string text = b.substr(at, end - at);
    at = end + 1;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.find('\0') != std::string::npos) return "a NUL byte in the header";
    std::istringstream words(text);
    std::vector<std::string> f;
    for (std::string w; words >> w;) f.push_back(w);
    if (f.empty()) continue;
    if (f[0] == "end_header") break;
    const bool magic = f.size() == 1 && f[0] == "ply";
    const std::string why = *line > 1 ? header_line(f, h)
                            : magic   ? ""
                                      : "not a PLY file: the first line must be 'ply'";
    if (!why.empty()) return why;
  }
  h->data_at = at;
  h->lines = *line;
  return "";
}

// The data: values one at a time, from ASCII lines (an element item a line) or bytes.
class Values {
 public:
  Values(const std::string& b, const Header& h) : b_(b), enc_(h.encoding), at_(h.data_at) {
    line_ = h.lines;
  }
  bool ascii() const { return enc_ == Encoding::kAscii; }
  int line() const { return line_; }
  size_t offset() const { return at_; }
  size_t item_offset() const { return item_at_; }  // where the current item began

  // An ASCII item's line; false at the end of the file.
  bool begin_item() {
    item_at_ = at_;
    if (!ascii()) return true;
    words_.clear();
    next_ = 0;
    while (words_.empty()) {
      if (at_ >= b_.size()) return false;
      size_t end = b_.find('\n', at_);
      if (end == std::string::npos) end = b_.size();
      std::istringstream words(b_.substr(at_, end - at_));
      for (std::string w; words >> w;) words_.push_back(w);
      at_ = end + 1;
      ++line_;
    }
    return true;
  }
  // The word the last ASCII value was read from.
  std::string_view last_word() const { return words_[next_ - 1]; }
  bool item_done() const { return !ascii() || next_ == words_.size(); }

  // The next value as a double; false with *why.
  bool value(Kind k, double* v, std::string* why) {
    if (ascii()) return text_value(k, v, why);
    const size_t n = size_of(k);
    if (at_ + n > b_.size()) {
      *why = "the file ends inside the data";
      return false;
    }
    uint64_t u = 0;
    for (size_t i = 0; i < n; ++i) {
      const uint64_t byte = uint8_t(b_[at_ + (enc_ == Encoding::kLittle ? i : n - 1 - i)]);
      u |= byte << (8 * i);
    }
    at_ += n;
    *v = decode(k, u);  // may be NaN: only the coordinates kept must be finite
    return true;
  }

 private:
  static double decode(Kind k, uint64_t u) {
    switch (k) {
      case Kind::kI8:
        return double(int8_t(uint8_t(u)));
      case Kind::kI16:
        return double(int16_t(uint16_t(u)));
      case Kind::kI32:
        return double(int32_t(uint32_t(u)));
      case Kind::kF32: {
        const uint32_t w = uint32_t(u);
        float f;
        std::memcpy(&f, &w, sizeof f);
        return double(f);
      }
      case Kind::kF64: {
        double d;
        std::memcpy(&d, &u, sizeof d);
        return d;
      }
      default:
        return double(u);
    }
  }

  bool text_value(Kind k, double* v, std::string* why) {
    if (next_ >= words_.size()) {
      *why = "the line ends early: expected more values for this element";
      return false;
    }
    const std::string& w = words_[next_++];
    char* end = nullptr;
    *v = std::strtod(w.c_str(), &end);
    const bool integer = k != Kind::kF32 && k != Kind::kF64;
    if (end != w.c_str() + w.size() || (integer && *v != std::floor(*v))) {
      *why = std::string("'") + excerpt(w) + "' is not " + (integer ? "an integer" : "a number");
      return false;
    }
    return true;
  }

  const std::string& b_;
  Encoding enc_;
  size_t at_;
  int line_ = 0;
  std::vector<std::string> words_;
  size_t next_ = 0;
  size_t item_at_ = 0;
};

struct PlyData {
  std::vector<double> xyz;
  CoordinateRounding rounding;
  std::vector<int> face_where;  // each face's line (ASCII) or byte offset (binary)
};

// A coordinate's rounding: its printed digits, or its binary type's.
void note_rounding(const Values& in, Kind k, CoordinateRounding* rounding) {
  if (in.ascii())
    rounding->note_text(in.last_word());
  else
    rounding->note_binary(k == Kind::kF32 ? 23 : k == Kind::kF64 ? 52 : 0);
}

// One element's items: the vertices' x y z and the faces' corners kept, the rest read past.
std::string read_element(const Element& e, Values* in, PlyData* d, ObjModel* out) {
  int xyz_at[3] = {-1, -1, -1}, corners_at = -1;
  for (size_t i = 0; i < e.props.size(); ++i) {
    const Property& p = e.props[i];
    for (int a = 0; a < 3; ++a)
      if (e.name == "vertex" && !p.list && p.name == std::string(1, char('x' + a)))
        xyz_at[a] = int(i);
    if (e.name == "face" && p.list && (p.name == "vertex_indices" || p.name == "vertex_index"))
      corners_at = int(i);
  }
  if (e.name == "vertex" && (xyz_at[0] < 0 || xyz_at[1] < 0 || xyz_at[2] < 0))
    return "the vertex element has no x, y and z properties";
  if (e.name == "face" && corners_at < 0)
    return "the face element has no list property vertex_indices (or vertex_index)";
  std::string why;
  for (uint64_t item = 0; item < e.count; ++item) {
    if (!in->begin_item()) return "the file ends before " + e.name + " " + std::to_string(item);
    const int where = in->ascii() ? in->line() : int(in->item_offset());
    double c[3] = {0, 0, 0};
    std::vector<uint32_t> corners;
    for (size_t i = 0; i < e.props.size(); ++i) {
      const Property& p = e.props[i];
      double v = 0;
      if (!in->value(p.list ? p.count_kind : p.kind, &v, &why)) return why;
      if (!p.list) {
        for (int a = 0; a < 3; ++a)
          if (int(i) == xyz_at[a]) {
            c[a] = v;
            note_rounding(*in, p.kind, &d->rounding);
          }
        continue;
      }
      if (!(v >= 0 && v < 4294967296.0)) return "a list length that is not a count";
      for (uint64_t j = 0, n = uint64_t(v); j < n; ++j) {
        double index = 0;
        if (!in->value(p.kind, &index, &why)) return why;
        if (int(i) == corners_at) corners.push_back(index < 0 ? ~0u : uint32_t(index));
      }
    }
    if (!in->item_done()) return "more values on the line than the " + e.name + " element has";
    if (e.name == "vertex" && !(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
      return "vertex " + std::to_string(item) + ": a coordinate is not a finite number";
    if (e.name == "vertex") d->xyz.insert(d->xyz.end(), c, c + 3);
    if (e.name != "face") continue;
    if (corners.size() < 3)
      return "a face needs at least 3 vertices, found " + std::to_string(corners.size());
    out->faces.push_back(corners);
    d->face_where.push_back(where);
  }
  return "";
}

}  // namespace

InputError read_ply(const std::string& bytes, const std::string& name, ObjModel* out) {
  *out = ObjModel{};
  Header h;
  int line = 0;
  std::string why = read_header(bytes, &h, &line);
  if (!why.empty()) return {name, line, why};
  Values in(bytes, h);
  PlyData d;
  for (const Element& e : h.elements) {
    why = read_element(e, &in, &d, out);
    if (why.empty()) continue;
    if (in.ascii()) return {name, in.line(), why};
    return {name, 0, "byte " + std::to_string(in.item_offset()) + ": " + why};
  }
  const size_t n = d.xyz.size() / 3;
  if (n == 0) return {name, h.lines, "no vertices"};
  for (size_t f = 0; f < out->faces.size(); ++f)
    for (uint32_t c : out->faces[f])
      if (c >= n) {
        const std::string what = "face " + std::to_string(f) + ": vertex index " +
                                 (c == ~0u ? std::string("below 0") : std::to_string(c)) +
                                 " is not in 0.." + std::to_string(n - 1);
        if (in.ascii()) return {name, d.face_where[f], what};
        return {name, 0, "byte " + std::to_string(d.face_where[f]) + ": " + what};
      }
  for (int where : d.face_where) out->face_lines.push_back(in.ascii() ? uint32_t(where) : 0u);
  place_vertices(d.xyz, d.rounding, out);
  edges_from_faces(out);
  return {};
}

}  // namespace haloplot::host
