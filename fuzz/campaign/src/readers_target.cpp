#include "certimesh/fuzz/campaign/readers_target.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "certimesh/fuzz/campaign/case_seed.h"
#include "certimesh/fuzz/campaign/named_target.h"
#include "certimesh/fuzz/recipes.h"
#include "certimesh/io/format_error.h"
#include "certimesh/io/gmsh_format.h"
#include "certimesh/io/medit_format.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/io/off_format.h"
#include "certimesh/io/stl_format.h"
#include "certimesh/io/triangle_format.h"
#include "certimesh/io/vtu_format.h"
#include "mesh_data_invariants.h"
#include "payload_text.h"

namespace certimesh::fuzz::campaign {

namespace {

namespace fs = std::filesystem;
using io::Index;
using io::Label;
using io::MeshData;
using Companions = std::vector<std::pair<std::string, std::string>>;

constexpr std::size_t kMaxInputBytes = 8192;

// ---- Files on disk, for the Triangle/TetGen writer and reader (which take paths): a private
// folder per call, removed afterwards, so that threads never share one.

class ScratchFolder {
 public:
  ScratchFolder() {
    static std::atomic<std::uint64_t> counter{0};
    path_ = fs::temp_directory_path() /
            ("certimesh-fuzz-readers-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)));
    fs::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Writes `m` as X.<ext> with certimesh's Triangle/TetGen writer; returns the main file and
// every companion the writer made.
std::pair<std::string, Companions> triangle_files(const MeshData& m, const std::string& ext) {
  ScratchFolder dir;
  io::write_triangle_format(m, dir.path() / ("x." + ext));
  std::string main;
  Companions companions;
  for (const char* e : {"node", "ele", "face", "edge", "poly", "smesh"}) {
    const fs::path p = dir.path() / (std::string("x.") + e);
    if (!fs::exists(p)) continue;
    if (e == ext) main = file_text(p);
    else companions.emplace_back(e, file_text(p));
  }
  return {std::move(main), std::move(companions)};
}

bool is_triangle_family(const std::string& ext) {
  return ext == "node" || ext == "ele" || ext == "face" || ext == "edge" || ext == "poly" || ext == "smesh";
}

MeshData certimesh_read(const std::string& ext, const std::string& contents, const Companions& companions) {
  if (ext == "mesh") return io::parse_medit_format("f.mesh", contents);
  if (ext == "msh") return io::parse_gmsh_format("f.msh", contents);
  if (ext == "vtu") return io::parse_vtu_format("f.vtu", contents);
  if (ext == "off") return io::parse_off_format("f.off", contents);
  if (ext == "stl") return io::parse_stl_format("f.stl", contents);
  return io::parse_triangle_format("f." + ext, contents, [&](const fs::path& p) -> std::optional<std::string> {
    for (const auto& [e, text] : companions)
      if (p.extension() == "." + e) return text;
    return std::nullopt;
  });
}

// ---- Random valid data, one shape per format.

double draw_coordinate(SplitMixSource& s) {
  switch (s.below(6)) {
    case 0: return static_cast<double>(draw_int(s, -3, 3));
    case 1: return static_cast<double>(draw_int(s, -64, 64)) / 8.0;
    case 2: return draw_unit_interval(s);
    case 3: return std::ldexp(static_cast<double>(draw_int(s, 1, 7)), s.below(2) ? 1000 : -1060);
    case 4: return -0.0;
    default: return std::ldexp(draw_unit_interval(s), static_cast<int>(draw_int(s, -40, 40)));
  }
}

Label draw_label(SplitMixSource& s) { return static_cast<Label>(draw_int(s, -2, 5)); }

// A label list of all zeros reads back empty ("empty = all 0", mesh_data.h), which is the
// same data but not the same bytes: a drawn list has a non-zero label.
void not_all_zero(std::vector<Label>& labels) {
  if (!labels.empty() && std::all_of(labels.begin(), labels.end(), [](Label l) { return l == 0; })) labels.front() = 1;
}

// `k` distinct indices below n (n >= k).
void push_cell(SplitMixSource& s, std::size_t n, std::size_t k, std::vector<Index>& cells) {
  std::vector<Index> c;
  while (c.size() < k) {
    const auto i = static_cast<Index>(s.below(n));
    if (std::find(c.begin(), c.end(), i) == c.end()) c.push_back(i);
  }
  cells.insert(cells.end(), c.begin(), c.end());
}

void add_cells(SplitMixSource& s, std::size_t n, std::size_t k, std::vector<Index>& cells, std::vector<Label>& labels) {
  const std::size_t count = s.below(6);
  const bool labelled = s.below(2) == 0;
  for (std::size_t i = 0; i < count; ++i) {
    push_cell(s, n, k, cells);
    if (labelled) labels.push_back(draw_label(s));
  }
  not_all_zero(labels);
}

MeshData draw_points(SplitMixSource& s, int dimension) {
  MeshData m;
  m.dimension = dimension;
  const std::size_t n = 4 + s.below(8);
  for (std::size_t i = 0; i < n * static_cast<std::size_t>(dimension); ++i) m.coordinates.push_back(draw_coordinate(s));
  if (s.below(2) == 0)
    for (std::size_t i = 0; i < n; ++i) m.point_labels.push_back(draw_label(s));
  not_all_zero(m.point_labels);
  return m;
}

void add_domain_points(SplitMixSource& s, MeshData& m) {
  const auto dim = static_cast<std::size_t>(m.dimension);
  for (std::size_t h = s.below(3); h > 0; --h)
    for (std::size_t k = 0; k < dim; ++k) m.holes.push_back(draw_coordinate(s));
  const std::size_t regions = s.below(3);
  const bool constrained = s.below(2) == 0;
  for (std::size_t r = 0; r < regions; ++r) {
    for (std::size_t k = 0; k < dim; ++k) m.region_points.push_back(draw_coordinate(s));
    m.region_attributes.push_back(static_cast<double>(draw_label(s)));
    if (constrained) m.region_max_measures.push_back(s.below(3) == 0 ? -1.0 : draw_unit_interval(s) + 1.0);
  }
}

// A .smesh facet is one polygon without holes; a .poly facet may have several of both.
void add_facets(SplitMixSource& s, MeshData& m, bool smesh) {
  io::FacetList& f = m.facets;
  const std::size_t n = m.point_count();
  const bool labelled = s.below(2) == 0;
  for (std::size_t facet = 1 + s.below(3); facet > 0; --facet) {
    for (std::size_t p = smesh ? 1 : 1 + s.below(2); p > 0; --p) {
      push_cell(s, n, 3 + s.below(2), f.corners);
      f.polygon_end.push_back(f.corners.size());
    }
    f.facet_end.push_back(f.polygon_end.size());
    if (!smesh && s.below(4) == 0)
      for (int k = 0; k < 3; ++k) f.holes.push_back(draw_coordinate(s));
    f.hole_end.push_back(f.holes.size() / 3);
    if (labelled) f.labels.push_back(draw_label(s));
  }
  not_all_zero(f.labels);
}

std::string coordinates_text(const MeshData& m, std::size_t i) {
  std::string out;
  for (std::size_t k = 0; k < 3; ++k) {
    out.push_back(' ');
    io::append_double(out, m.coordinates[3 * i + k]);
  }
  return out;
}

// OFF and STL: written here (certimesh has no writer for them).
std::string off_text(SplitMixSource& s, const MeshData& m) {
  std::vector<std::vector<Index>> faces;
  for (std::size_t f = 1 + s.below(5); f > 0; --f) {
    std::vector<Index> c;
    push_cell(s, m.point_count(), s.below(3) == 0 ? 4 : 3, c);
    faces.push_back(c);
  }
  std::string out = s.below(2) ? "OFF\n# a comment\n" : "OFF ";
  out += std::to_string(m.point_count()) + " " + std::to_string(faces.size()) + " 0\n";
  for (std::size_t i = 0; i < m.point_count(); ++i) {
    out += coordinates_text(m, i);
    out.push_back('\n');
  }
  for (const auto& f : faces) {
    out += std::to_string(f.size());
    for (const Index i : f) {
      out.push_back(' ');
      out += std::to_string(i);
    }
    out += s.below(4) == 0 ? " 255 0 0\n" : "\n";
  }
  return out;
}

std::string stl_ascii_text(SplitMixSource& s, const MeshData& m) {
  std::string out;
  for (std::size_t solid = 1 + s.below(2); solid > 0; --solid) {
    out += "solid part\n";
    for (std::size_t t = 1 + s.below(4); t > 0; --t) {
      std::vector<Index> c;
      push_cell(s, m.point_count(), 3, c);
      out += "  facet normal 0 0 1\n    outer loop\n";
      for (const Index i : c) {
        out += "      vertex";
        out += coordinates_text(m, i);
        out.push_back('\n');
      }
      out += "    endloop\n  endfacet\n";
    }
    out += "endsolid part\n";
  }
  return out;
}

std::string stl_binary_text(SplitMixSource& s, const MeshData& m) {
  std::string out(80, ' ');
  out.replace(0, 5, "solid");  // binary files that begin with "solid" must still read as binary
  const auto count = static_cast<std::uint32_t>(1 + s.below(4));
  const auto put = [&out](const void* p, std::size_t n) { out.append(static_cast<const char*>(p), n); };
  put(&count, 4);  // little-endian hosts only, like the format
  for (std::uint32_t t = 0; t < count; ++t) {
    std::vector<Index> c;
    push_cell(s, m.point_count(), 3, c);
    const float normal[3] = {0, 0, 1};
    put(normal, sizeof normal);
    for (const Index i : c)
      for (std::size_t k = 0; k < 3; ++k) {
        const auto v = static_cast<float>(m.coordinates[3 * i + k]);
        put(&v, 4);
      }
    const std::uint16_t attribute = 0;
    put(&attribute, 2);
  }
  return out;
}

struct Input {
  bool pristine = false;  // written by certimesh's writer and not mutated
  std::string ext;
  std::string main;
  Companions companions;
};

// A valid file of one format, from certimesh's writer where it has one.
Input draw_valid_input(SplitMixSource& s) {
  static constexpr const char* kFormats[] = {"mesh", "msh", "vtu", "ele", "node", "poly", "poly", "smesh", "off", "stl", "stl"};
  const std::size_t which = s.below(std::size(kFormats));
  Input in{true, kFormats[which], {}, {}};
  const int dim = which == 5 ? 2 : which >= 6 ? 3 : static_cast<int>(2 + s.below(2));
  MeshData m = draw_points(s, dim);
  const std::size_t n = m.point_count();
  switch (which) {
    case 0: case 1: case 2:
      add_cells(s, n, 2, m.segments, m.segment_labels);
      add_cells(s, n, 3, m.triangles, m.triangle_labels);
      if (dim == 3) add_cells(s, n, 4, m.tetrahedra, m.tetrahedron_labels);
      if (which == 1 && dim == 3) m.coordinates[2] = 1.0;  // Gmsh: 3D only with a z != 0 (gmsh_format.h)
      in.main = which == 0 ? io::format_medit(m) : which == 1 ? io::format_gmsh(m) : io::format_vtu(m);
      return in;
    case 3:
      if (dim == 3) {
        add_cells(s, n, 4, m.tetrahedra, m.tetrahedron_labels);
        add_cells(s, n, 3, m.triangles, m.triangle_labels);
      } else {
        add_cells(s, n, 3, m.triangles, m.triangle_labels);
      }
      add_cells(s, n, 2, m.segments, m.segment_labels);
      break;
    case 4: break;
    case 5:
      add_cells(s, n, 2, m.segments, m.segment_labels);
      add_domain_points(s, m);
      break;
    case 6: case 7:
      add_facets(s, m, which == 7);
      add_domain_points(s, m);
      break;
    case 8: in.main = off_text(s, m); break;
    case 9: in.main = stl_ascii_text(s, m); break;
    default: in.main = stl_binary_text(s, m); break;
  }
  if (which >= 8) {
    in.pristine = false;  // not certimesh's writer
    return in;
  }
  auto [main, companions] = triangle_files(m, in.ext);
  in.main = std::move(main);
  in.companions = std::move(companions);
  return in;
}

// ---- Mutations.

const char* const kHostileNumbers[] = {"0", "-1", "4294967296", "4294967295", "99999999999999999999", "1e999", "-1e999",
                                       "nan", "inf", "-0", "0.5", "1e-320", "2147483648", "-2147483649", "0x10", "1.5e"};

std::vector<std::pair<std::size_t, std::size_t>> number_spans(const std::string& t) {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  for (std::size_t i = 0; i < t.size();) {
    const bool starts = std::isdigit(static_cast<unsigned char>(t[i])) ||
                        ((t[i] == '-' || t[i] == '+') && i + 1 < t.size() && std::isdigit(static_cast<unsigned char>(t[i + 1])));
    if (!starts || (i > 0 && std::isalnum(static_cast<unsigned char>(t[i - 1])))) {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < t.size() && (std::isdigit(static_cast<unsigned char>(t[j])) || std::strchr(".eE+-", t[j]))) ++j;
    spans.emplace_back(i, j - i);
    i = j;
  }
  return spans;
}

std::vector<std::pair<std::size_t, std::size_t>> line_spans(const std::string& t) {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  for (std::size_t i = 0; i < t.size();) {
    const std::size_t e = std::min(t.find('\n', i), t.size());
    spans.emplace_back(i, std::min(e + 1, t.size()) - i);
    i = e + 1;
  }
  return spans;
}

void mutate(SplitMixSource& s, std::string& t) {
  if (t.empty()) {
    t.push_back(static_cast<char>(s.below(256)));
    return;
  }
  switch (s.below(9)) {
    case 0: t[s.below(t.size())] ^= static_cast<char>(1u << s.below(8)); return;
    case 1: t.insert(t.begin() + static_cast<std::ptrdiff_t>(s.below(t.size() + 1)), " \n-0.e#\t$"[s.below(9)]); return;
    case 2: t.erase(s.below(t.size()), 1); return;
    case 3: case 4: {
      const auto lines = line_spans(t);
      const std::size_t l = s.below(lines.size());
      const auto [b, n] = lines[l];
      if (s.below(2)) t.erase(b, n);
      else if (l + 1 < lines.size()) t = t.substr(0, b) + t.substr(lines[l + 1].first, lines[l + 1].second) + t.substr(b, n) + t.substr(b + n + lines[l + 1].second);
      else t.insert(b, t.substr(b, n));
      return;
    }
    case 5: t.resize(s.below(t.size())); return;
    default: {
      const auto numbers = number_spans(t);
      if (numbers.empty()) return;
      const auto [b, n] = numbers[s.below(numbers.size())];
      std::string with = kHostileNumbers[s.below(std::size(kHostileNumbers))];
      if (s.below(4) == 0) {  // the number + 1: a count or an index one too large
        const std::string old = t.substr(b, n);
        if (old.find_first_not_of("0123456789") == std::string::npos && n < 18) with = std::to_string(std::stoll(old) + 1);
      }
      t.replace(b, n, with);
      return;
    }
  }
}

// ---- Payload: "EXT HEX [EXT HEX]...".

std::string hex(const std::string& bytes) {
  if (bytes.empty()) return "-";
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  for (const unsigned char c : bytes) {
    out.push_back(digits[c >> 4]);
    out.push_back(digits[c & 15]);
  }
  return out;
}

std::string unhex(const std::string& word) {
  if (word == "-") return {};
  if (word.size() % 2 != 0) throw MalformedPayload("odd number of hex digits");
  std::string out;
  for (std::size_t i = 0; i < word.size(); i += 2) {
    const auto nibble = [&](char c) -> int {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      throw MalformedPayload(std::string("not a hex digit: '") + c + "'");
    };
    out.push_back(static_cast<char>(nibble(word[i]) * 16 + nibble(word[i + 1])));
  }
  return out;
}

std::string payload_of(const Input& in) {
  std::string p = in.pristine ? "pristine " : "mutated ";
  p += in.ext;
  p.push_back(' ');
  p += hex(in.main);
  for (const auto& [e, text] : in.companions) p += " " + e + " " + hex(text);
  return p;
}

// ---- The checks.

std::size_t line_count(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1; }

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](double x, double y) {
           return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
         });
}

// The first field where the round trip changed the data, or nullptr.
const char* changed_field(const MeshData& a, const MeshData& b) {
  if (a.dimension != b.dimension) return "dimension";
  if (!same_bits(a.coordinates, b.coordinates)) return "coordinates";
  if (a.point_labels != b.point_labels) return "point labels";
  if (a.segments != b.segments || a.segment_labels != b.segment_labels) return "segments";
  if (a.triangles != b.triangles || a.triangle_labels != b.triangle_labels) return "triangles";
  if (!same_bits(a.triangle_attributes, b.triangle_attributes)) return "triangle attributes";
  if (a.tetrahedra != b.tetrahedra || a.tetrahedron_labels != b.tetrahedron_labels) return "tetrahedra";
  if (!(a.facets == b.facets) || !same_bits(a.facets.holes, b.facets.holes)) return "facets";
  if (!same_bits(a.holes, b.holes)) return "holes";
  if (!same_bits(a.region_points, b.region_points) || !same_bits(a.region_attributes, b.region_attributes) ||
      !same_bits(a.region_max_measures, b.region_max_measures))
    return "regions";
  return nullptr;
}

// The files certimesh's writer makes of `m` for a file of extension `ext`: the main one and
// its companions.
std::pair<std::string, Companions> written_files(const MeshData& m, const std::string& ext) {
  if (ext == "mesh") return {io::format_medit(m), {}};
  if (ext == "msh") return {io::format_gmsh(m), {}};
  if (ext == "vtu") return {io::format_vtu(m), {}};
  return triangle_files(m, ext);
}

// Writes `m` in the format it was read from (OFF and STL, read only: Medit, or .smesh when
// it has polygon facets) and reads it back.
MeshData round_trip(const MeshData& m, const std::string& ext) {
  if (ext == "mesh") return io::parse_medit_format("r.mesh", io::format_medit(m));
  if (ext == "msh") return io::parse_gmsh_format("r.msh", io::format_gmsh(m));
  if (ext == "vtu") return io::parse_vtu_format("r.vtu", io::format_vtu(m));
  if ((ext == "off" || ext == "stl") && m.facets.empty()) return io::parse_medit_format("r.mesh", io::format_medit(m));
  const std::string as = is_triangle_family(ext) ? (ext == "face" || ext == "edge" ? "ele" : ext) : "smesh";
  ScratchFolder dir;
  io::write_triangle_format(m, dir.path() / ("r." + as));
  return io::read_triangle_format(dir.path() / ("r." + as));
}

std::optional<Finding> check(const ReaderKernel& kernel, const Input& in) {
  const std::string payload = payload_of(in);
  const auto found = [&](const std::string& what) { return Finding{"readers ." + in.ext + ": " + what, payload}; };
  MeshData m;
  try {
    m = kernel.read(in.ext, in.main, in.companions);
  } catch (const io::FormatError& e) {
    std::optional<std::size_t> lines;
    if (e.file() == "f." + in.ext) lines = line_count(in.main);
    for (const auto& [ext, text] : in.companions)
      if (e.file() == "f." + ext) lines = line_count(text);
    if (!lines) return found("the error names a file it did not read: '" + e.file() + "'");
    if (e.line() > *lines) return found("the error names line " + std::to_string(e.line()) + " of a " + std::to_string(*lines) + "-line file");
    if (std::string_view(e.what()).size() > 512) return found("an error message longer than 512 bytes");
    return std::nullopt;
  } catch (const std::exception& e) {
    return found(std::string("an exception other than FormatError: ") + e.what());
  }
  if (const auto defect = certimesh::testing::mesh_data_defect(m)) return found("accepted data breaks an invariant: " + *defect);
  MeshData back;
  try {
    back = round_trip(m, in.ext);
  } catch (const std::exception& e) {
    return found(std::string("the round trip of accepted data fails: ") + e.what());
  }
  if (const char* field = changed_field(m, back)) return found(std::string("the round trip changes the ") + field);
  // A file certimesh wrote reads back to the data it was written from: re-writing what was
  // read gives the same bytes (a reader that loses a bit or a label shows here).
  if (in.pristine) {
    const auto [main, companions] = written_files(m, in.ext);
    if (main != in.main || companions != in.companions) return found("re-writing a file certimesh wrote gives other bytes");
  }
  return std::nullopt;
}

class ReadersTarget final : public KernelTarget<ReaderKernel> {
 public:
  using KernelTarget::KernelTarget;
  std::optional<Finding> run_case(std::uint64_t seed) const override {
    SplitMixSource s(seed);
    Input in = draw_valid_input(s);
    // Mostly the main file; sometimes the .node companion.
    std::string* file = &in.main;
    if (!in.companions.empty() && s.below(4) == 0) file = &in.companions[s.below(in.companions.size())].second;
    for (std::uint64_t k = s.below(4); k > 0; --k) {
      mutate(s, *file);
      in.pristine = false;
    }
    if (file->size() > kMaxInputBytes) file->resize(kMaxInputBytes);
    return check(kernel_, in);
  }
  std::optional<Finding> replay(std::string_view payload) const override {
    PayloadReader words(payload);
    Input in;
    const std::string state = words.next_word();
    if (state != "pristine" && state != "mutated") throw MalformedPayload("the payload starts with neither 'pristine' nor 'mutated'");
    in.pristine = state == "pristine";
    in.ext = words.next_word();
    in.main = unhex(words.next_word());
    while (!words.at_end()) {
      std::string ext = words.next_word();
      in.companions.emplace_back(std::move(ext), unhex(words.next_word()));
    }
    return check(kernel_, in);
  }

};

}  // namespace

ReaderKernel certimesh_reader_kernel() { return {certimesh_read}; }

std::unique_ptr<Target> make_readers_target(const ReaderKernel& kernel, std::string name, std::string description) {
  return std::make_unique<ReadersTarget>(kernel, std::move(name), std::move(description));
}

std::unique_ptr<Target> make_readers_target() {
  return make_readers_target(certimesh_reader_kernel(), "readers",
                             "every io/ reader on mutated valid files: FormatError naming an existing line, or data "
                             "meeting mesh_data.h's invariants that round-trips bit for bit through its writer");
}

}  // namespace certimesh::fuzz::campaign
