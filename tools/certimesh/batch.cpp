// `certimesh predicates`: the streaming batch interface. Format: see README.md and --help.
//
// One query per line: a command name, then its coordinates (decimal or C99 hex-float, parsed
// exactly: strtod is correctly rounded on glibc). Output: one answer per query line. Blank
// lines and `#` comments produce no output. A malformed line produces no output on stdout and
// `error: line N: why` on stderr; processing continues.
//
// Memory is constant in the number of lines: one reused line buffer, one fixed output buffer.
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>

#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "cli.h"

// The intersection commands need the kernel's intersection tests; tools/certimesh/CMakeLists.txt
// sets CERTIMESH_CLI_HAS_INTERSECTION when the predicates library builds them.
#ifndef CERTIMESH_CLI_HAS_INTERSECTION
#define CERTIMESH_CLI_HAS_INTERSECTION 0
#endif
#if CERTIMESH_CLI_HAS_INTERSECTION
#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/segment_segment_2d.h"
#include "certimesh/predicates/intersection/tetrahedron_triangle.h"
#include "certimesh/predicates/intersection/triangle_segment_2d.h"
#include "certimesh/predicates/intersection/triangle_segment_3d.h"
#include "certimesh/predicates/intersection/triangle_triangle_3d.h"
#include "certimesh/predicates/intersection/vertex.h"
#endif

namespace certimesh::cli {
namespace {

namespace cp = certimesh::predicates;

enum class Command { orient2d, orient3d, incircle, insphere, seg_seg2d, tri_seg2d, tri_seg3d,
                     tet_tri, tri_tri3d };

struct CommandSpec {
  std::string_view name;
  Command command;
  int points;     // number of input points
  int dimension;  // 2 or 3
};

constexpr std::array<CommandSpec, 9> kCommands{{
    {"orient2d", Command::orient2d, 3, 2},   {"orient3d", Command::orient3d, 4, 3},
    {"incircle", Command::incircle, 4, 2},   {"insphere", Command::insphere, 5, 3},
    {"seg_seg2d", Command::seg_seg2d, 4, 2}, {"tri_seg2d", Command::tri_seg2d, 5, 2},
    {"tri_seg3d", Command::tri_seg3d, 5, 3}, {"tet_tri", Command::tet_tri, 7, 3},
    {"tri_tri3d", Command::tri_tri3d, 6, 3},
}};
constexpr int kMaxNumbers = 21;

// Fixed-size output buffer written with fwrite: no iostreams, no per-line syscalls.
class Output {
 public:
  explicit Output(bool line_buffered) : line_buffered_(line_buffered) {}
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;
  ~Output() { flush(); }
  void line(std::string_view text) {
    if (used_ + text.size() + 1 > buffer_.size()) flush();
    std::memcpy(buffer_.data() + used_, text.data(), text.size());
    used_ += text.size();
    buffer_[used_++] = '\n';
    if (line_buffered_) flush();
  }
  void flush() {
    if (used_ > 0) std::fwrite(buffer_.data(), 1, used_, stdout);
    used_ = 0;
    if (line_buffered_) std::fflush(stdout);
  }

 private:
  std::array<char, 1 << 16> buffer_{};
  std::size_t used_ = 0;
  bool line_buffered_;
};

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 40;
  std::string s = "'";
  s.append(token.substr(0, kShown));
  if (token.size() > kShown) s.append("...");
  s.append("'");
  return s;
}

// Parses one NUL-terminated token as a double, exactly (correctly rounded). The whole token
// must be consumed. NaN and infinity tokens are refused, and so are finite literals whose
// value overflows double (like 1e400). Literals below the subnormal range round, correctly,
// to a subnormal or zero: that is their nearest double, and they are accepted.
bool parse_number(const char* token, double& out, std::string& why) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(token, &end);
  const std::string_view tok(token);
  if (end == token || *end != '\0') {
    why = "malformed number " + quoted(tok);
    return false;
  }
  if (std::isnan(v)) {
    why = "NaN is not a coordinate: " + quoted(tok);
    return false;
  }
  if (std::isinf(v)) {
    const bool literal_infinity = tok.find_first_of("iI") != std::string_view::npos;
    why = literal_infinity ? "infinity is not a coordinate: " + quoted(tok)
                           : "number out of range (overflows double): " + quoted(tok);
    return false;
  }
  out = v;
  return true;
}

const char* sign_text(cp::Sign s) {
  switch (s) {
    case cp::Sign::negative: return "-1";
    case cp::Sign::zero: return "0";
    case cp::Sign::positive: return "1";
  }
  return "?";
}

const char* sign_text(cp::FilteredSign s) {
  switch (s) {
    case cp::FilteredSign::negative: return "-1";
    case cp::FilteredSign::uncertain: return "?";
    case cp::FilteredSign::positive: return "1";
  }
  return "?";
}

// Vertex identity inside one line: points whose coordinates are bit-identical are the same
// vertex (so two elements of one line that repeat a point share that vertex); the id of a
// point is the index of the first point of the line equal to it. Bit patterns, not ==:
// -0.0 and +0.0 are two vertices at the same place, which touch (vertex.h).
[[maybe_unused]] std::uint64_t coordinate_bits(double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return bits;
}

[[maybe_unused]] std::array<std::int64_t, 7> vertex_ids(const double* c, int points, int dimension) {
  std::array<std::int64_t, 7> ids{};
  for (int i = 0; i < points; ++i) {
    ids[static_cast<std::size_t>(i)] = i;
    for (int j = 0; j < i; ++j) {
      bool same = true;
      for (int k = 0; k < dimension; ++k) {
        same = same && coordinate_bits(c[i * dimension + k]) == coordinate_bits(c[j * dimension + k]);
      }
      if (same) {
        ids[static_cast<std::size_t>(i)] = ids[static_cast<std::size_t>(j)];
        break;
      }
    }
  }
  return ids;
}

cp::Point2 p2(const double* c, int i) { return {c[2 * i], c[2 * i + 1]}; }
cp::Point3 p3(const double* c, int i) { return {c[3 * i], c[3 * i + 1], c[3 * i + 2]}; }

const char* answer_predicate(Command command, BatchMode mode, const double* c) {
  switch (command) {
    case Command::orient2d:
      switch (mode) {
        case BatchMode::exact: return sign_text(cp::orient2d(p2(c, 0), p2(c, 1), p2(c, 2)));
        case BatchMode::filter: return sign_text(cp::orient2d_filtered(p2(c, 0), p2(c, 1), p2(c, 2)));
        case BatchMode::sos: return sign_text(cp::orient2d_sos(p2(c, 0), p2(c, 1), p2(c, 2)));
      }
      break;
    case Command::orient3d:
      switch (mode) {
        case BatchMode::exact: return sign_text(cp::orient3d(p3(c, 0), p3(c, 1), p3(c, 2), p3(c, 3)));
        case BatchMode::filter:
          return sign_text(cp::orient3d_filtered(p3(c, 0), p3(c, 1), p3(c, 2), p3(c, 3)));
        case BatchMode::sos: return sign_text(cp::orient3d_sos(p3(c, 0), p3(c, 1), p3(c, 2), p3(c, 3)));
      }
      break;
    case Command::incircle:
      switch (mode) {
        case BatchMode::exact: return sign_text(cp::incircle(p2(c, 0), p2(c, 1), p2(c, 2), p2(c, 3)));
        case BatchMode::filter:
          return sign_text(cp::incircle_filtered(p2(c, 0), p2(c, 1), p2(c, 2), p2(c, 3)));
        case BatchMode::sos: return sign_text(cp::incircle_sos(p2(c, 0), p2(c, 1), p2(c, 2), p2(c, 3)));
      }
      break;
    case Command::insphere:
      switch (mode) {
        case BatchMode::exact:
          return sign_text(cp::insphere(p3(c, 0), p3(c, 1), p3(c, 2), p3(c, 3), p3(c, 4)));
        case BatchMode::filter:
          return sign_text(cp::insphere_filtered(p3(c, 0), p3(c, 1), p3(c, 2), p3(c, 3), p3(c, 4)));
        case BatchMode::sos:
          return sign_text(cp::insphere_sos(p3(c, 0), p3(c, 1), p3(c, 2), p3(c, 3), p3(c, 4)));
      }
      break;
    default: break;
  }
  return nullptr;
}

#if CERTIMESH_CLI_HAS_INTERSECTION
template <std::size_t N>
std::array<cp::Vertex2, N> vertices2(const double* c, const std::array<std::int64_t, 7>& ids,
                                     int first) {
  std::array<cp::Vertex2, N> v{};
  for (std::size_t i = 0; i < N; ++i) {
    const int k = first + static_cast<int>(i);
    v[i] = cp::Vertex2{p2(c, k), ids[static_cast<std::size_t>(k)]};
  }
  return v;
}

template <std::size_t N>
std::array<cp::Vertex3, N> vertices3(const double* c, const std::array<std::int64_t, 7>& ids,
                                     int first) {
  std::array<cp::Vertex3, N> v{};
  for (std::size_t i = 0; i < N; ++i) {
    const int k = first + static_cast<int>(i);
    v[i] = cp::Vertex3{p3(c, k), ids[static_cast<std::size_t>(k)]};
  }
  return v;
}

const char* overlap_text(cp::Overlap o) {
  return o == cp::Overlap::intersect ? "intersect" : "disjoint";
}

// Filter mode is the conservative intersection mode (errs only towards "intersect");
// exact and sos modes use the exact mode.
const char* answer_intersection(Command command, BatchMode mode, const double* c,
                                const CommandSpec& spec) {
  const cp::IntersectionMode m =
      mode == BatchMode::filter ? cp::IntersectionMode::conservative : cp::IntersectionMode::exact;
  const auto ids = vertex_ids(c, spec.points, spec.dimension);
  switch (command) {
    case Command::seg_seg2d:
      return overlap_text(cp::segment_segment_2d(vertices2<2>(c, ids, 0), vertices2<2>(c, ids, 2), m));
    case Command::tri_seg2d:
      return overlap_text(cp::triangle_segment_2d(vertices2<3>(c, ids, 0), vertices2<2>(c, ids, 3), m));
    case Command::tri_seg3d:
      return overlap_text(cp::triangle_segment_3d(vertices3<3>(c, ids, 0), vertices3<2>(c, ids, 3), m));
    case Command::tet_tri:
      return overlap_text(cp::tetrahedron_triangle(vertices3<4>(c, ids, 0), vertices3<3>(c, ids, 4), m));
    case Command::tri_tri3d:
      return overlap_text(cp::triangle_triangle_3d(vertices3<3>(c, ids, 0), vertices3<3>(c, ids, 3), m));
    default: break;
  }
  return nullptr;
}
#endif

bool is_blank(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n' || ch == '\v' || ch == '\f'; }

// Splits the line in place into NUL-terminated tokens, stopping at a `#` comment.
// Returns the number of tokens found (at most max_tokens + 1, to detect extra tokens).
int tokenize(char* line, char** tokens, int max_tokens) {
  int count = 0;
  char* p = line;
  while (*p != '\0' && *p != '#') {
    while (is_blank(*p)) ++p;
    if (*p == '\0' || *p == '#') break;
    if (count <= max_tokens) tokens[count] = p;
    ++count;
    while (*p != '\0' && *p != '#' && !is_blank(*p)) ++p;
    if (*p == '#') {
      *p = '\0';
      break;
    }
    if (*p != '\0') *p++ = '\0';
  }
  return count;
}

}  // namespace

int run_batch(const BatchOptions& options) {
  Output out(options.line_buffered);
  char* line = nullptr;
  std::size_t capacity = 0;
  std::size_t line_number = 0;
  bool any_error = false;
  char* tokens[kMaxNumbers + 2];
  double coordinates[kMaxNumbers];

  auto fail = [&](const std::string& why) {
    out.flush();  // keep stdout and stderr in order for a reader of both
    std::fprintf(stderr, "error: line %zu: %s\n", line_number, why.c_str());
    any_error = true;
  };

  while (getline(&line, &capacity, stdin) != -1) {
    ++line_number;
    const int count = tokenize(line, tokens, kMaxNumbers + 1);
    if (count == 0) continue;  // blank line or comment

    const std::string_view name(tokens[0]);
    const CommandSpec* spec = nullptr;
    for (const CommandSpec& s : kCommands) {
      if (s.name == name) spec = &s;
    }
    if (spec == nullptr) {
      fail("unknown command " + quoted(name));
      continue;
    }
    const int expected = spec->points * spec->dimension;
    if (count - 1 != expected) {
      fail(std::string(spec->name) + " expects " + std::to_string(expected) + " numbers, got " +
           std::to_string(count - 1));
      continue;
    }
    std::string why;
    bool ok = true;
    for (int i = 0; i < expected && ok; ++i) {
      ok = parse_number(tokens[i + 1], coordinates[i], why);
      if (!ok) why = "number " + std::to_string(i + 1) + ": " + why;
    }
    if (!ok) {
      fail(why);
      continue;
    }
    try {
      const char* answer = answer_predicate(spec->command, options.mode, coordinates);
#if CERTIMESH_CLI_HAS_INTERSECTION
      if (answer == nullptr) answer = answer_intersection(spec->command, options.mode, coordinates, *spec);
#endif
      if (answer == nullptr) {
        fail("not available");
        continue;
      }
      out.line(answer);
    } catch (const std::exception& e) {
      fail(e.what());
    }
  }
  std::free(line);
  out.flush();
  std::fflush(stdout);
  if (std::ferror(stdin)) {
    std::fprintf(stderr, "error: reading stdin failed\n");
    return 1;
  }
  return any_error ? 1 : 0;
}

}  // namespace certimesh::cli
