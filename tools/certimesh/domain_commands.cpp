// `certimesh domain SCRIPT -o OUT.poly`: constructive geometry of planar domains from a small
// script (docs/domains.md), one statement per line:
//   rect NAME x0 y0 x1 y1        disc NAME cx cy r step        polygon NAME x y x y x y ...
//   union NAME A B               difference NAME A B           intersection NAME A B
//   output NAME
// `#` starts a comment. Errors are `error: FILE:LINE: why`; exit 0 written, 1 bad script or
// invalid result, 2 unreadable script or unwritable output.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "certimesh/generators/domain/constructive_geometry_2.h"
#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"
#include "cli.h"

namespace certimesh::cli {

namespace {

namespace gen = certimesh::generators;

// A statement the script refuses: the line and why (the caller adds the file name).
struct ScriptError {
  std::size_t line;
  std::string why;
};

struct Statement {
  std::size_t line = 0;
  std::vector<std::string> words;
};

// The statements of a script, and in `lines` how many lines it has.
std::vector<Statement> statements_of(std::istream& in, std::size_t& lines) {
  std::vector<Statement> out;
  std::string text;
  lines = 0;
  for (std::size_t line = 1; std::getline(in, text); ++line) {
    lines = line;
    if (const auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
    std::istringstream words(text);
    Statement s{line, {}};
    for (std::string w; words >> w;) s.words.push_back(w);
    if (!s.words.empty()) out.push_back(std::move(s));
  }
  return out;
}

double number(const Statement& s, std::size_t i) {
  const std::string& w = s.words[i];
  double value = 0.0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
  if (ec != std::errc{} || end != w.data() + w.size() || !std::isfinite(value)) {
    throw ScriptError{s.line, "'" + w + "' is not a finite number"};
  }
  return value;
}

class Script {
 public:
  void run(const Statement& s) {
    const std::string& verb = s.words[0];
    if (verb == "rect") return define(s, 6, [&] {
        return gen::rectangle_region(number(s, 2), number(s, 3), number(s, 4), number(s, 5));
      });
    if (verb == "disc") return define(s, 6, [&] {
        return gen::disc_region({number(s, 2), number(s, 3)}, number(s, 4), number(s, 5));
      });
    if (verb == "polygon") return define_polygon(s);
    if (verb == "union") return define(s, 4, [&] { return gen::region_union(use(s, 2), use(s, 3)); });
    if (verb == "difference") return define(s, 4, [&] { return gen::region_difference(use(s, 2), use(s, 3)); });
    if (verb == "intersection") return define(s, 4, [&] { return gen::region_intersection(use(s, 2), use(s, 3)); });
    if (verb == "output") return set_output(s);
    throw ScriptError{s.line, "unknown statement '" + verb +
                                  "' (expected rect, disc, polygon, union, difference, intersection or output)"};
  }

  // The domain of the output region, or a ScriptError at the output line.
  gen::PlanarDomain domain(std::size_t last_line) const {
    if (!output_) throw ScriptError{last_line, "the script has no 'output NAME' line"};
    try {
      return gen::to_planar_domain(regions_.at(output_->name), 1);
    } catch (const gen::InvalidDomain& e) {
      throw ScriptError{output_->line, "region '" + output_->name + "' is not a valid domain: " +
                                           e.problems().front().message};
    }
  }

 private:
  struct Output {
    std::string name;
    std::size_t line;
  };

  template <class Make>
  void define(const Statement& s, std::size_t words, Make make) {
    if (s.words.size() != words) {
      throw ScriptError{s.line, "'" + s.words[0] + "' takes " + std::to_string(words - 1) + " arguments, got " +
                                    std::to_string(s.words.size() - 1)};
    }
    const std::string& name = s.words[1];
    if (const auto it = defined_at_.find(name); it != defined_at_.end()) {
      throw ScriptError{s.line, "'" + name + "' is already defined on line " + std::to_string(it->second)};
    }
    try {
      regions_[name] = make();
    } catch (const std::invalid_argument& e) {
      throw ScriptError{s.line, e.what()};
    }
    defined_at_[name] = s.line;
  }

  void define_polygon(const Statement& s) {
    if (s.words.size() < 8 || s.words.size() % 2 != 0) {
      throw ScriptError{s.line, "'polygon NAME x y x y x y ...' needs 3 or more coordinate pairs"};
    }
    define(s, s.words.size(), [&] {
      std::vector<gen::Point2> points;
      for (std::size_t i = 2; i < s.words.size(); i += 2) points.push_back({number(s, i), number(s, i + 1)});
      return gen::polygon_region(points);
    });
  }

  const gen::Region2& use(const Statement& s, std::size_t i) const {
    const auto it = regions_.find(s.words[i]);
    if (it == regions_.end()) throw ScriptError{s.line, "'" + s.words[i] + "' is not defined above"};
    return it->second;
  }

  void set_output(const Statement& s) {
    if (s.words.size() != 2) throw ScriptError{s.line, "'output' takes one region name"};
    if (output_) throw ScriptError{s.line, "a second 'output' (the first is on line " + std::to_string(output_->line) + ")"};
    use(s, 1);
    output_ = Output{s.words[1], s.line};
  }

  std::map<std::string, gen::Region2> regions_;
  std::map<std::string, std::size_t> defined_at_;
  std::optional<Output> output_;
};

}  // namespace

int run_domain(const std::string& script_path, const std::string& output) {
  std::ifstream in(script_path);
  if (!in) {
    std::fprintf(stderr, "error: %s: cannot open the script\n", script_path.c_str());
    return 2;
  }
  gen::PlanarDomain domain;
  try {
    std::size_t lines = 0;
    const std::vector<Statement> statements = statements_of(in, lines);
    Script script;
    for (const Statement& s : statements) script.run(s);
    domain = script.domain(std::max<std::size_t>(lines, 1));
  } catch (const ScriptError& e) {
    std::fprintf(stderr, "error: %s:%zu: %s\n", script_path.c_str(), e.line, e.why.c_str());
    return 1;
  }
  try {
    io::write_mesh(gen::to_mesh_data(domain), output);
  } catch (const io::FormatError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  std::printf("%s: %zu vertices, %zu segments, %zu holes\n", output.c_str(), domain.points.size(),
              domain.segments.size(), domain.holes.size());
  return 0;
}

}  // namespace certimesh::cli
