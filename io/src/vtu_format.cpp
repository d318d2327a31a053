#include "certimesh/io/vtu_format.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <type_traits>
#include <string_view>
#include <utility>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"
#include "text_writer.h"

namespace certimesh::io {

namespace {

// ---------------------------------------------------------------------------------------------
// A minimal XML tokenizer for the restricted schema of .vtu files: elements, attributes,
// character data, comments and <?...?> declarations. No DTD, no CDATA, no entities in the
// parts certimesh reads (refused or left as they are). Depth is bounded so that a hostile
// file cannot exhaust the stack.

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::string_view text;     // the first non-blank run of character data directly inside
  std::size_t line = 0;      // line of the start tag
  std::size_t text_line = 0; // line where `text` begins
  std::vector<XmlElement> children;

  const std::string* attribute(std::string_view key) const {
    for (const auto& [k, v] : attributes) {
      if (k == key) return &v;
    }
    return nullptr;
  }
};

constexpr int kMaxDepth = 32;

bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
         c == '-' || c == '.';
}

class XmlParser {
 public:
  XmlParser(const std::string& name, std::string_view text) : name_(name), text_(text) {}

  XmlElement parse_document() {
    if (starts_with("\xEF\xBB\xBF")) pos_ = 3;  // a UTF-8 byte order mark, as some editors save
    skip_misc();
    if (at_end()) fail("no XML element (empty or not a .vtu file)");
    if (!starts_with("<") || starts_with("</")) fail("expected an XML element");
    XmlElement root = parse_element(0);
    skip_misc();
    if (!at_end()) fail("content after the root element");
    return root;
  }

  [[noreturn]] void fail(const std::string& why) const { throw FormatError(name_, line_, why); }

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  bool starts_with(std::string_view s) const { return text_.substr(pos_).starts_with(s); }

  void advance(std::size_t n) {
    const std::size_t end = std::min(text_.size(), pos_ + n);
    line_ += static_cast<std::size_t>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                                 text_.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
    pos_ = end;
  }
  void skip_spaces() {
    while (!at_end() && is_xml_space(text_[pos_])) advance(1);
  }
  void skip_past(std::string_view terminator, const char* what) {
    const std::size_t found = text_.find(terminator, pos_);
    if (found == std::string_view::npos) fail(std::string("unterminated ") + what);
    advance(found + terminator.size() - pos_);
  }
  // Whitespace, comments and <?...?> declarations between elements.
  void skip_misc() {
    for (;;) {
      skip_spaces();
      if (starts_with("<!--")) {
        skip_past("-->", "comment");
      } else if (starts_with("<?")) {
        skip_past("?>", "<?...?> declaration");
      } else if (starts_with("<!")) {
        fail("DOCTYPE and CDATA are not supported in .vtu files");
      } else {
        return;
      }
    }
  }

  std::string parse_name() {
    const std::size_t begin = pos_;
    while (!at_end() && is_name_char(text_[pos_])) ++pos_;
    if (pos_ == begin) fail("expected an XML name");
    return std::string(text_.substr(begin, pos_ - begin));
  }

  void parse_attribute(XmlElement& element) {
    std::string key = parse_name();
    skip_spaces();
    if (at_end() || text_[pos_] != '=') fail("expected '=' after attribute " + key);
    advance(1);
    skip_spaces();
    if (at_end() || (text_[pos_] != '"' && text_[pos_] != '\'')) fail("expected a quoted value for attribute " + key);
    const char quote = text_[pos_];
    advance(1);
    const std::size_t end = text_.find(quote, pos_);
    if (end == std::string_view::npos) fail("unterminated value of attribute " + key);
    std::string value(text_.substr(pos_, end - pos_));
    advance(end + 1 - pos_);
    if (element.attribute(key) != nullptr) fail("attribute " + key + " appears twice");
    element.attributes.emplace_back(std::move(key), std::move(value));
  }

  // At '<' of a start tag.
  XmlElement parse_element(int depth) {
    if (depth > kMaxDepth) fail("XML nested deeper than " + std::to_string(kMaxDepth) + " elements");
    XmlElement element;
    element.line = line_;
    advance(1);
    element.name = parse_name();
    for (;;) {
      skip_spaces();
      if (at_end()) fail("unterminated start tag <" + element.name + ">");
      if (starts_with("/>")) {
        advance(2);
        return element;
      }
      if (text_[pos_] == '>') break;
      parse_attribute(element);
    }
    advance(1);
    parse_content(element, depth);
    return element;
  }

  void parse_content(XmlElement& element, int depth) {
    for (;;) {
      if (at_end()) fail("unexpected end of file inside <" + element.name + "> of line " + std::to_string(element.line));
      if (starts_with("<!--")) {
        skip_past("-->", "comment");
      } else if (starts_with("</")) {
        advance(2);
        const std::string closing = parse_name();
        if (closing != element.name) fail("</" + closing + "> closes <" + element.name + "> of line " + std::to_string(element.line));
        skip_spaces();
        if (at_end() || text_[pos_] != '>') fail("expected '>' after </" + closing);
        advance(1);
        return;
      } else if (starts_with("<!")) {
        fail("CDATA is not supported in .vtu files");
      } else if (starts_with("<")) {
        element.children.push_back(parse_element(depth + 1));
      } else {
        parse_text(element);
      }
    }
  }

  void parse_text(XmlElement& element) {
    const std::size_t begin = pos_;
    const std::size_t line = line_;
    std::size_t end = text_.find('<', pos_);
    if (end == std::string_view::npos) end = text_.size();
    const std::string_view run = text_.substr(begin, end - begin);
    advance(end - pos_);
    const auto first = std::find_if_not(run.begin(), run.end(), is_xml_space);
    if (first == run.end()) return;
    if (!element.text.empty()) fail("<" + element.name + "> has character data in several pieces");
    // The text and its line start at its first non-blank character (errors name that line).
    element.text = run.substr(static_cast<std::size_t>(first - run.begin()));
    element.text_line = line + static_cast<std::size_t>(std::count(run.begin(), first, '\n'));
  }

  const std::string& name_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

// ---------------------------------------------------------------------------------------------
// DataArray decoding.

enum class Scalar { int8, uint8, int16, uint16, int32, uint32, int64, uint64, float32, float64 };

std::optional<Scalar> scalar_of(std::string_view type) {
  static constexpr std::array<std::pair<std::string_view, Scalar>, 10> kTypes{{
      {"Int8", Scalar::int8}, {"UInt8", Scalar::uint8}, {"Int16", Scalar::int16}, {"UInt16", Scalar::uint16},
      {"Int32", Scalar::int32}, {"UInt32", Scalar::uint32}, {"Int64", Scalar::int64}, {"UInt64", Scalar::uint64},
      {"Float32", Scalar::float32}, {"Float64", Scalar::float64}}};
  for (const auto& [name, scalar] : kTypes) {
    if (name == type) return scalar;
  }
  return std::nullopt;
}

std::size_t size_of(Scalar s) {
  switch (s) {
    case Scalar::int8: case Scalar::uint8: return 1;
    case Scalar::int16: case Scalar::uint16: return 2;
    case Scalar::int32: case Scalar::uint32: case Scalar::float32: return 4;
    case Scalar::int64: case Scalar::uint64: case Scalar::float64: return 8;
  }
  return 8;
}

bool is_float(Scalar s) { return s == Scalar::float32 || s == Scalar::float64; }

// What the file as a whole says about binary arrays.
struct Encoding {
  bool little_endian = true;
  std::string compressor;        // empty: none; "vtkZLibDataCompressor" is the one supported
  std::size_t header_bytes = 4;  // UInt32 (VTK's default) or UInt64
};

constexpr std::string_view kZlib = "vtkZLibDataCompressor";

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

class ArrayDecoder {
 public:
  ArrayDecoder(const std::string& file, const Encoding& encoding) : file_(file), encoding_(encoding) {}

  /// The values of an integer DataArray (any integer type); `what` names it in errors. A
  /// compressed array may declare at most `max_values` values (the most the caller can use),
  /// so that a small hostile file cannot make the reader inflate gigabytes.
  std::vector<std::int64_t> integers(const XmlElement& array, std::string_view what, std::size_t max_values) const {
    const Scalar scalar = scalar_type(array);
    if (is_float(scalar)) fail(array, std::string(what) + " must have an integer type, not " + *array.attribute("type"));
    return is_binary(array) ? decode_binary<std::int64_t>(array, scalar, max_values) : parse_ascii<std::int64_t>(array);
  }

  /// The values of a Float32/Float64 DataArray (`max_values` as for integers()).
  std::vector<double> reals(const XmlElement& array, std::string_view what, std::size_t max_values) const {
    const Scalar scalar = scalar_type(array);
    if (!is_float(scalar)) fail(array, std::string(what) + " must have type Float32 or Float64, not " + *array.attribute("type"));
    return is_binary(array) ? decode_binary<double>(array, scalar, max_values) : parse_ascii<double>(array);
  }

  [[noreturn]] void fail(const XmlElement& e, const std::string& why) const { throw FormatError(file_, e.line, why); }
  [[noreturn]] void fail_at(std::size_t line, const std::string& why) const { throw FormatError(file_, line, why); }

 private:
  Scalar scalar_type(const XmlElement& array) const {
    const std::string* type = array.attribute("type");
    if (type == nullptr) fail(array, "DataArray without a type attribute");
    const auto scalar = scalar_of(*type);
    if (!scalar) fail(array, "DataArray type '" + *type + "' is not supported");
    return *scalar;
  }

  bool is_binary(const XmlElement& array) const {
    const std::string* format = array.attribute("format");
    if (format == nullptr || *format == "ascii") return false;
    if (*format == "appended") fail(array, "appended data (format=\"appended\") is not supported; write ascii or inline binary");
    if (*format != "binary") fail(array, "DataArray format '" + *format + "' is not supported");
    if (!encoding_.compressor.empty() && encoding_.compressor != kZlib) {
      fail(array, "compressor '" + encoding_.compressor + "' is not supported (certimesh reads " + std::string(kZlib) +
                      "); write with meshio compression=\"zlib\" or None");
    }
    if (!encoding_.little_endian) fail(array, "BigEndian binary data is not supported");
    return true;
  }

  template <typename T>
  std::vector<T> parse_ascii(const XmlElement& array) const {
    std::vector<T> values;
    std::size_t line = array.text_line;
    const std::string_view text = array.text;
    std::size_t pos = 0;
    while (pos < text.size()) {
      if (is_xml_space(text[pos])) {
        if (text[pos] == '\n') ++line;
        ++pos;
        continue;
      }
      std::size_t end = pos;
      while (end < text.size() && !is_xml_space(text[end])) ++end;
      values.push_back(parse_number<T>(text.substr(pos, end - pos), line));
      pos = end;
    }
    return values;
  }

  template <typename T>
  T parse_number(std::string_view token, std::size_t line) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    T value{};
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (result.ec == std::errc::result_out_of_range) fail_at(line, "value '" + std::string(token) + "' is out of range");
    if (result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
      fail_at(line, "expected a number, got '" + std::string(token) + "'");
    }
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(value)) fail_at(line, "value is not finite ('" + std::string(token) + "')");
    }
    return value;
  }

  // Base64 in groups of four characters; a padded group may be followed by another block
  // (VTK writes the header and the data as two base64 blocks, meshio as one).
  std::vector<unsigned char> decode_base64(const XmlElement& array) const {
    std::vector<unsigned char> bytes;
    std::array<int, 4> group{};
    std::size_t filled = 0;
    std::size_t padding = 0;
    for (char c : array.text) {
      if (is_xml_space(c)) continue;
      if (c == '=') {
        if (filled < 2) fail_at(array.text_line, "malformed base64 data (misplaced '=')");
        group[filled++] = 0;
        ++padding;
      } else {
        const int v = base64_value(c);
        if (v < 0 || padding > 0) fail_at(array.text_line, "malformed base64 data (character '" + std::string(1, c) + "')");
        group[filled++] = v;
      }
      if (filled == 4) {
        const unsigned bits = (static_cast<unsigned>(group[0]) << 18) | (static_cast<unsigned>(group[1]) << 12) |
                              (static_cast<unsigned>(group[2]) << 6) | static_cast<unsigned>(group[3]);
        const std::array<unsigned char, 3> out{static_cast<unsigned char>(bits >> 16),
                                               static_cast<unsigned char>(bits >> 8), static_cast<unsigned char>(bits)};
        bytes.insert(bytes.end(), out.begin(), out.begin() + static_cast<std::ptrdiff_t>(3 - padding));
        filled = 0;
        padding = 0;
      }
    }
    if (filled != 0) fail_at(array.text_line, "malformed base64 data (length not a multiple of 4)");
    return bytes;
  }

  static std::uint64_t little_endian_unsigned(const unsigned char* p, std::size_t size) {
    std::uint64_t value = 0;
    for (std::size_t i = size; i-- > 0;) value = (value << 8) | p[i];
    return value;
  }

  template <typename T>
  static T convert(const unsigned char* p, Scalar s) {
    const std::uint64_t bits = little_endian_unsigned(p, size_of(s));
    switch (s) {
      case Scalar::int8: return static_cast<T>(static_cast<std::int8_t>(bits));
      case Scalar::int16: return static_cast<T>(static_cast<std::int16_t>(bits));
      case Scalar::int32: return static_cast<T>(static_cast<std::int32_t>(bits));
      case Scalar::int64: return static_cast<T>(static_cast<std::int64_t>(bits));
      case Scalar::uint8: case Scalar::uint16: case Scalar::uint32: return static_cast<T>(bits);
      case Scalar::uint64: return static_cast<T>(bits);  // values >= 2^63 are refused by the caller
      case Scalar::float32: {
        float f;
        const auto narrow = static_cast<std::uint32_t>(bits);
        std::memcpy(&f, &narrow, sizeof f);
        return static_cast<T>(f);
      }
      case Scalar::float64: {
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return static_cast<T>(d);
      }
    }
    return T{};
  }

  // The raw bytes of an uncompressed array: one header value (the byte count), then the data.
  std::vector<unsigned char> uncompressed_payload(const XmlElement& array, std::vector<unsigned char> bytes) const {
    const std::size_t header = encoding_.header_bytes;
    if (bytes.size() < header) fail_at(array.text_line, "binary DataArray shorter than its header");
    const std::uint64_t declared = little_endian_unsigned(bytes.data(), header);
    if (declared > bytes.size() - header) {
      fail_at(array.text_line, "binary DataArray header declares " + std::to_string(declared) + " bytes, it holds " +
                                   std::to_string(bytes.size() - header));
    }
    bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(header + declared), bytes.end());
    bytes.erase(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(header));
    return bytes;
  }

  // The raw bytes of a zlib-compressed array (VTK's layout): header values [number of blocks,
  // block size, size of the last block (0: full), compressed size of each block], then the
  // blocks, each one zlib stream. At most `max_bytes` are inflated.
  std::vector<unsigned char> inflated_payload(const XmlElement& array, const std::vector<unsigned char>& bytes,
                                              std::size_t max_bytes) const {
    const std::size_t h = encoding_.header_bytes;
    const auto header_value = [&](std::size_t i) { return little_endian_unsigned(bytes.data() + i * h, h); };
    if (bytes.size() < 3 * h) fail_at(array.text_line, "compressed DataArray shorter than its header");
    const std::uint64_t blocks = header_value(0);
    const std::uint64_t block_size = header_value(1);
    const std::uint64_t last_size = header_value(2);
    if (blocks > bytes.size() / h - 3) fail_at(array.text_line, "compressed DataArray header declares " + std::to_string(blocks) + " blocks, more than it can hold");
    if (last_size > block_size) fail_at(array.text_line, "compressed DataArray: last block larger than the block size");
    // Only full blocks and the last one are inflated: bound them before multiplying.
    const std::uint64_t last = last_size == 0 ? block_size : last_size;
    if (blocks > 0 && (last > max_bytes || blocks - 1 > (max_bytes - last) / std::max<std::uint64_t>(block_size, 1))) {
      fail_at(array.text_line, "compressed DataArray declares more data than the piece can use");
    }
    const std::uint64_t total = blocks == 0 ? 0 : (blocks - 1) * block_size + last;
    if (total > max_bytes) fail_at(array.text_line, "compressed DataArray declares more data than the piece can use");
    std::vector<unsigned char> out(static_cast<std::size_t>(total));
    std::size_t offset = static_cast<std::size_t>(3 + blocks) * h;
    std::size_t written = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::uint64_t packed = header_value(static_cast<std::size_t>(3 + b));
      if (packed > bytes.size() - offset) fail_at(array.text_line, "compressed DataArray truncated in block " + std::to_string(b));
      const std::uint64_t expected = b + 1 == blocks && last_size != 0 ? last_size : block_size;
      auto length = static_cast<uLongf>(expected);
      const int status = uncompress(out.data() + written, &length, bytes.data() + offset, static_cast<uLong>(packed));
      if (status != Z_OK || length != expected) {
        fail_at(array.text_line, "compressed DataArray block " + std::to_string(b) + " is corrupt (zlib status " + std::to_string(status) + ")");
      }
      written += static_cast<std::size_t>(expected);
      offset += static_cast<std::size_t>(packed);
    }
    return out;
  }

  template <typename T>
  std::vector<T> decode_binary(const XmlElement& array, Scalar scalar, std::size_t max_values) const {
    const std::size_t width = size_of(scalar);
    const std::vector<unsigned char> payload =
        encoding_.compressor.empty()
            ? uncompressed_payload(array, decode_base64(array))
            : inflated_payload(array, decode_base64(array), max_values > SIZE_MAX / width ? SIZE_MAX : max_values * width);
    if (payload.size() % width != 0) fail_at(array.text_line, "binary DataArray byte count is not a multiple of its type size");
    std::vector<T> values;
    values.reserve(payload.size() / width);
    for (std::size_t offset = 0; offset < payload.size(); offset += width) {
      if (scalar == Scalar::uint64 && payload[offset + 7] >= 0x80) fail_at(array.text_line, "UInt64 value above 2^63");
      const T value = convert<T>(payload.data() + offset, scalar);
      if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(value)) fail_at(array.text_line, "binary DataArray value is not finite");
      }
      values.push_back(value);
    }
    return values;
  }

  const std::string& file_;
  Encoding encoding_;
};

// ---------------------------------------------------------------------------------------------
// Interpreting the tree.

constexpr std::int64_t kVtkVertex = 1;
constexpr std::int64_t kVtkLine = 3;
constexpr std::int64_t kVtkTriangle = 5;
constexpr std::int64_t kVtkTetra = 10;

std::vector<Index>& cells_of_vtu_kind(MeshData& mesh, std::size_t kind) {
  return kind == 0 ? mesh.segments : kind == 1 ? mesh.triangles : mesh.tetrahedra;
}
std::vector<Label>& labels_of_vtu_kind(MeshData& mesh, std::size_t kind) {
  return kind == 0 ? mesh.segment_labels : kind == 1 ? mesh.triangle_labels : mesh.tetrahedron_labels;
}

class VtuInterpreter {
 public:
  VtuInterpreter(const std::string& file, std::size_t file_bytes) : file_(file), file_bytes_(file_bytes) {}

  MeshData interpret(const XmlElement& root) {
    read_root_attributes(root);
    const ArrayDecoder decoder(file_, encoding_);
    const XmlElement& grid = only_child(root, "UnstructuredGrid");
    const XmlElement* piece = nullptr;
    std::optional<int> dimension;
    for (const XmlElement& child : grid.children) {
      if (child.name == "Piece") {
        if (piece != nullptr) fail(child, "more than one <Piece> (certimesh reads single-piece files)");
        piece = &child;
      } else if (child.name == "FieldData") {
        dimension = read_dimension_field(decoder, child);
      } else {
        fail(child, "unexpected <" + child.name + "> in <UnstructuredGrid>");
      }
    }
    if (piece == nullptr) fail(grid, "<UnstructuredGrid> has no <Piece>");
    return read_piece(decoder, *piece, dimension);
  }

 private:
  [[noreturn]] void fail(const XmlElement& e, const std::string& why) const { throw FormatError(file_, e.line, why); }

  void read_root_attributes(const XmlElement& root) {
    if (root.name != "VTKFile") fail(root, "the root element is <" + root.name + ">, expected <VTKFile>");
    const std::string* type = root.attribute("type");
    if (type == nullptr || *type != "UnstructuredGrid") {
      fail(root, "VTKFile type '" + (type ? *type : std::string()) + "' is not supported (certimesh reads UnstructuredGrid)");
    }
    const std::string* version = root.attribute("version");
    if (version != nullptr && *version != "0.1" && *version != "1.0") {
      fail(root, "VTKFile version '" + *version + "' is not supported (certimesh reads 0.1 and 1.0)");
    }
    const std::string* order = root.attribute("byte_order");
    encoding_.little_endian = order == nullptr || *order == "LittleEndian";
    if (order != nullptr && *order != "LittleEndian" && *order != "BigEndian") fail(root, "unknown byte_order '" + *order + "'");
    const std::string* header = root.attribute("header_type");
    if (header != nullptr && *header != "UInt32" && *header != "UInt64") fail(root, "header_type '" + *header + "' is not supported");
    encoding_.header_bytes = header != nullptr && *header == "UInt64" ? 8 : 4;
    const std::string* compressor = root.attribute("compressor");
    encoding_.compressor = compressor == nullptr ? std::string() : *compressor;
    for (const XmlElement& child : root.children) {
      if (child.name == "AppendedData") fail(child, "appended data is not supported; write ascii or inline binary");
    }
  }

  const XmlElement& only_child(const XmlElement& parent, std::string_view name) const {
    const XmlElement* found = nullptr;
    for (const XmlElement& child : parent.children) {
      if (child.name != name) fail(child, "unexpected <" + child.name + "> in <" + parent.name + ">");
      if (found != nullptr) fail(child, "a second <" + child.name + ">");
      found = &child;
    }
    if (found == nullptr) fail(parent, "<" + parent.name + "> has no <" + std::string(name) + ">");
    return *found;
  }

  std::optional<int> read_dimension_field(const ArrayDecoder& decoder, const XmlElement& field_data) const {
    std::optional<int> dimension;
    for (const XmlElement& array : field_data.children) {
      const std::string* name = array.attribute("Name");
      if (array.name != "DataArray" || name == nullptr || *name != "certimesh_dimension") continue;
      const auto values = decoder.integers(array, "certimesh_dimension", 1);
      if (values.size() != 1 || (values[0] != 2 && values[0] != 3)) fail(array, "certimesh_dimension must be one value, 2 or 3");
      dimension = static_cast<int>(values[0]);
    }
    return dimension;
  }

  std::size_t count_attribute(const XmlElement& piece, const char* key) const {
    const std::string* text = piece.attribute(key);
    if (text == nullptr) fail(piece, std::string("<Piece> has no ") + key);
    std::size_t value = 0;
    const auto result = std::from_chars(text->data(), text->data() + text->size(), value);
    if (result.ec != std::errc() || result.ptr != text->data() + text->size()) {
      fail(piece, std::string(key) + " '" + *text + "' is not a count");
    }
    // Every point or cell needs at least two characters of data: refuse before any work.
    if (value > file_bytes_ / 2) {
      fail(piece, std::string(key) + " " + *text + " cannot fit in a file of " + std::to_string(file_bytes_) + " bytes");
    }
    return value;
  }

  // The DataArray named `name` among `parent`'s children (or its only one, for <Points>).
  const XmlElement* find_array(const XmlElement& parent, std::string_view name) const {
    for (const XmlElement& child : parent.children) {
      if (child.name != "DataArray") fail(child, "unexpected <" + child.name + "> in <" + parent.name + ">");
      const std::string* n = child.attribute("Name");
      if (name.empty() || (n != nullptr && *n == name)) return &child;
    }
    return nullptr;
  }

  MeshData read_piece(const ArrayDecoder& decoder, const XmlElement& piece, std::optional<int> dimension) const {
    const std::size_t points = count_attribute(piece, "NumberOfPoints");
    const std::size_t cells = count_attribute(piece, "NumberOfCells");
    MeshData mesh;
    std::vector<double> xyz;
    std::vector<Label> cell_labels;
    bool has_cells = false;
    for (const XmlElement& child : piece.children) {
      if (child.name == "Points") {
        xyz = read_points(decoder, child, points);
      } else if (child.name == "Cells") {
        read_cells(decoder, child, points, cells, mesh);
        has_cells = true;
      } else if (child.name == "PointData") {
        if (const XmlElement* a = find_array(child, "label")) mesh.point_labels = read_labels(decoder, *a, points);
      } else if (child.name == "CellData") {
        if (const XmlElement* a = find_array(child, "label")) cell_labels = read_labels(decoder, *a, cells);
      } else {
        fail(child, "unexpected <" + child.name + "> in <Piece>");
      }
    }
    if (xyz.size() != 3 * points) fail(piece, "<Piece> has no <Points> for its " + std::to_string(points) + " points");
    if (!has_cells && cells != 0) fail(piece, "<Piece> has no <Cells> for its " + std::to_string(cells) + " cells");
    set_dimension_and_coordinates(piece, dimension, xyz, mesh);
    distribute_labels(cell_labels, mesh);
    return mesh;
  }

  std::vector<double> read_points(const ArrayDecoder& decoder, const XmlElement& points_element, std::size_t points) const {
    const XmlElement* array = find_array(points_element, "");
    if (array == nullptr) fail(points_element, "<Points> has no DataArray");
    const std::string* components = array->attribute("NumberOfComponents");
    if (components == nullptr || *components != "3") fail(*array, "Points must have NumberOfComponents=\"3\"");
    std::vector<double> xyz = decoder.reals(*array, "Points", 3 * points);
    if (xyz.size() != 3 * points) {
      fail(*array, "Points holds " + std::to_string(xyz.size()) + " values, NumberOfPoints " + std::to_string(points) +
                       " needs " + std::to_string(3 * points));
    }
    return xyz;
  }

  std::vector<Label> read_labels(const ArrayDecoder& decoder, const XmlElement& array, std::size_t count) const {
    const auto values = decoder.integers(array, "label", count);
    if (values.size() != count) {
      fail(array, "label holds " + std::to_string(values.size()) + " values, expected " + std::to_string(count));
    }
    std::vector<Label> labels;
    labels.reserve(values.size());
    for (std::int64_t v : values) {
      if (v < std::numeric_limits<Label>::min() || v > std::numeric_limits<Label>::max()) {
        fail(array, "label " + std::to_string(v) + " is not a 32-bit integer");
      }
      labels.push_back(static_cast<Label>(v));
    }
    return labels;
  }

  void read_cells(const ArrayDecoder& decoder, const XmlElement& cells_element, std::size_t points, std::size_t cells,
                  MeshData& mesh) const {
    const XmlElement* connectivity = find_array(cells_element, "connectivity");
    const XmlElement* offsets = find_array(cells_element, "offsets");
    const XmlElement* types = find_array(cells_element, "types");
    if (!connectivity || !offsets || !types) fail(cells_element, "<Cells> needs DataArrays connectivity, offsets and types");
    const auto nodes = decoder.integers(*connectivity, "connectivity", 4 * cells);
    const auto ends = decoder.integers(*offsets, "offsets", cells);
    const auto kinds = decoder.integers(*types, "types", cells);
    if (ends.size() != cells) fail(*offsets, "offsets holds " + std::to_string(ends.size()) + " values, NumberOfCells is " + std::to_string(cells));
    if (kinds.size() != cells) fail(*types, "types holds " + std::to_string(kinds.size()) + " values, NumberOfCells is " + std::to_string(cells));
    std::int64_t begin = 0;
    for (std::size_t c = 0; c < cells; ++c) {
      const std::int64_t end = ends[c];
      if (end < begin || end > static_cast<std::int64_t>(nodes.size())) {
        fail(*offsets, "offset " + std::to_string(end) + " of cell " + std::to_string(c) + " is out of order or beyond the connectivity");
      }
      append_cell(*types, *connectivity, kinds[c], c, nodes, {begin, end}, points, mesh);
      begin = end;
    }
  }

  // Appends one cell; records its kind in cell_kind_ (3 = skipped vertex) for the labels.
  void append_cell(const XmlElement& types, const XmlElement& connectivity, std::int64_t type, std::size_t c,
                   const std::vector<std::int64_t>& nodes, std::pair<std::int64_t, std::int64_t> range, std::size_t points,
                   MeshData& mesh) const {
    const auto [begin, end] = range;
    std::size_t kind = 3;
    std::int64_t arity = 1;
    if (type == kVtkLine) { kind = 0; arity = 2; }
    else if (type == kVtkTriangle) { kind = 1; arity = 3; }
    else if (type == kVtkTetra) { kind = 2; arity = 4; }
    else if (type != kVtkVertex) {
      fail(types, "cell " + std::to_string(c) + " has VTK type " + std::to_string(type) +
                      ", not supported (certimesh reads 3 line, 5 triangle, 10 tetra and skips 1 vertex)");
    }
    if (end - begin != arity) {
      fail(types, "cell " + std::to_string(c) + " of VTK type " + std::to_string(type) + " has " + std::to_string(end - begin) + " vertices");
    }
    cell_kind_.push_back(kind);
    if (kind == 3) return;
    for (std::int64_t i = begin; i < end; ++i) {
      const std::int64_t v = nodes[static_cast<std::size_t>(i)];
      if (v < 0 || static_cast<std::size_t>(v) >= points) {
        fail(connectivity, "cell " + std::to_string(c) + " names point " + std::to_string(v) + ", outside [0, " + std::to_string(points) + ")");
      }
      cells_of_vtu_kind(mesh, kind).push_back(static_cast<Index>(v));
    }
  }

  void distribute_labels(const std::vector<Label>& cell_labels, MeshData& mesh) const {
    if (cell_labels.empty()) return;
    std::array<std::vector<Label>, 3> per_kind;
    for (std::size_t c = 0; c < cell_kind_.size(); ++c) {
      if (cell_kind_[c] < 3) per_kind[cell_kind_[c]].push_back(cell_labels[c]);
    }
    for (std::size_t kind = 0; kind < 3; ++kind) {
      const auto& labels = per_kind[kind];
      if (std::any_of(labels.begin(), labels.end(), [](Label l) { return l != 0; })) labels_of_vtu_kind(mesh, kind) = labels;
    }
  }

  void set_dimension_and_coordinates(const XmlElement& piece, std::optional<int> dimension, const std::vector<double>& xyz,
                                     MeshData& mesh) const {
    const std::size_t points = xyz.size() / 3;
    std::size_t first_z = points;
    for (std::size_t i = 0; i < points && first_z == points; ++i) {
      if (xyz[3 * i + 2] != 0.0) first_z = i;
    }
    if (dimension == 2 && first_z != points) {
      fail(piece, "certimesh_dimension is 2 but point " + std::to_string(first_z) + " has z != 0");
    }
    mesh.dimension = dimension.value_or(!mesh.tetrahedra.empty() || first_z != points ? 3 : 2);
    const auto d = static_cast<std::size_t>(mesh.dimension);
    mesh.coordinates.reserve(points * d);
    for (std::size_t i = 0; i < points; ++i) {
      mesh.coordinates.insert(mesh.coordinates.end(), xyz.begin() + static_cast<std::ptrdiff_t>(3 * i),
                              xyz.begin() + static_cast<std::ptrdiff_t>(3 * i + d));
    }
  }

  const std::string& file_;
  std::size_t file_bytes_;
  Encoding encoding_;
  mutable std::vector<std::size_t> cell_kind_;
};

MeshData parse_vtu_text(const std::string& name, const std::string& contents) {
  const XmlElement root = XmlParser(name, contents).parse_document();
  return VtuInterpreter(name, contents.size()).interpret(root);
}

// ---------------------------------------------------------------------------------------------
// Writing

template <typename Values>
void append_integer_array(std::string& out, const char* type, const char* name, const Values& values) {
  out += "        <DataArray type=\"";
  out += type;
  out += "\" Name=\"";
  out += name;
  out += "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < values.size(); ++i) {
    detail::append_integer(out, values[i]);
    out += (i % 16 == 15 || i + 1 == values.size()) ? '\n' : ' ';
  }
  out += "        </DataArray>\n";
}

void append_vtu_points(std::string& out, const MeshData& mesh) {
  out += "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  const auto d = static_cast<std::size_t>(mesh.dimension);
  for (std::size_t i = 0; i < mesh.point_count(); ++i) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      append_double(out, axis < d ? mesh.coordinates[i * d + axis] : 0.0);
      out += axis == 2 ? '\n' : ' ';
    }
  }
  out += "        </DataArray>\n      </Points>\n";
}

void append_cells_and_labels(std::string& out, const MeshData& mesh) {
  const std::array<std::pair<const std::vector<Index>*, const std::vector<Label>*>, 3> kinds{
      {{&mesh.segments, &mesh.segment_labels}, {&mesh.triangles, &mesh.triangle_labels}, {&mesh.tetrahedra, &mesh.tetrahedron_labels}}};
  constexpr std::array<int, 3> kVtkTypes{static_cast<int>(kVtkLine), static_cast<int>(kVtkTriangle), static_cast<int>(kVtkTetra)};
  std::vector<std::uint64_t> connectivity;
  std::vector<std::uint64_t> offsets;
  std::vector<int> types;
  std::vector<Label> labels;
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const std::size_t arity = k + 2;
    const std::size_t count = kinds[k].first->size() / arity;
    for (std::size_t c = 0; c < count; ++c) {
      for (std::size_t i = 0; i < arity; ++i) connectivity.push_back((*kinds[k].first)[c * arity + i]);
      offsets.push_back(connectivity.size());
      types.push_back(kVtkTypes[k]);
      labels.push_back(kinds[k].second->empty() ? 0 : (*kinds[k].second)[c]);
    }
  }
  out += "      <Cells>\n";
  append_integer_array(out, "Int64", "connectivity", connectivity);
  append_integer_array(out, "Int64", "offsets", offsets);
  append_integer_array(out, "UInt8", "types", types);
  out += "      </Cells>\n      <CellData>\n";
  append_integer_array(out, "Int32", "label", labels);
  out += "      </CellData>\n";
}

std::size_t total_cells(const MeshData& mesh) {
  return mesh.segment_count() + mesh.triangle_count() + mesh.tetrahedron_count();
}

}  // namespace

MeshData read_vtu_format(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw FormatError(path.string(), 0, "cannot open the file for reading");
  const std::streamoff size = in.tellg();
  if (size < 0) throw FormatError(path.string(), 0, "cannot tell the file size");
  std::string contents(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(contents.data(), size)) throw FormatError(path.string(), 0, "read error");
  return parse_vtu_text(path.string(), contents);
}

MeshData parse_vtu_format(std::string name, std::string contents) { return parse_vtu_text(name, contents); }

namespace {

std::string format_vtu_named(const MeshData& mesh, const std::string& name) {
  detail::check_writable(mesh, name);
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      "  <UnstructuredGrid>\n"
      "    <FieldData>\n"
      "      <DataArray type=\"Int32\" Name=\"certimesh_dimension\" NumberOfTuples=\"1\" format=\"ascii\">";
  out += std::to_string(mesh.dimension);
  out += "</DataArray>\n    </FieldData>\n    <Piece NumberOfPoints=\"" + std::to_string(mesh.point_count()) +
         "\" NumberOfCells=\"" + std::to_string(total_cells(mesh)) + "\">\n";
  if (!mesh.point_labels.empty()) {
    out += "      <PointData>\n";
    append_integer_array(out, "Int32", "label", mesh.point_labels);
    out += "      </PointData>\n";
  }
  append_vtu_points(out, mesh);
  append_cells_and_labels(out, mesh);
  out += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

}  // namespace

std::string format_vtu(const MeshData& mesh) { return format_vtu_named(mesh, "(.vtu output)"); }

void write_vtu_format(const MeshData& mesh, const std::filesystem::path& path) {
  write_file_atomically(path, format_vtu_named(mesh, path.string()));
}

}  // namespace certimesh::io
