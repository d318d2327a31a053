// certimesh: the command-line tool. Subcommands: demo, predicates, convert, check, mesh,
// check-surface, domain, fuzz. See --help, and COMMAND --help for one command's options (help.cpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

#include "cli.h"

#ifndef CERTIMESH_VERSION
#define CERTIMESH_VERSION "unknown"
#endif

namespace {

constexpr const char* kHelp =
    "usage: certimesh <command> [options]\n"
    "\n"
    "commands:\n"
    "  demo                 naive floating point against certimesh on the classroom\n"
    "                       robustness examples; every answer re-checked with GMP\n"
    "  predicates [--mode exact|filter|sos] [--line-buffered]\n"
    "                       batch predicates: one query per stdin line, one answer per\n"
    "                       stdout line (default mode: exact)\n"
    "  convert IN OUT       convert a mesh between formats, chosen by extension:\n"
    "                       .node/.ele/.face/.poly (Triangle, TetGen), .mesh (Medit),\n"
    "                       .msh (Gmsh 4.1 ASCII), .vtu (VTK XML, for ParaView)\n"
    "  check MESH [--domain DOMAIN] [--certificate OUT.json] [--boundary-tolerance D]\n"
    "                       certify MESH exactly: oriented elements, conforming facets, an\n"
    "                       embedded boundary, a single cover; with DOMAIN (.poly in 2D; a\n"
    "                       TetGen .poly/.smesh or a closed surface mesh in 3D) also that\n"
    "                       MESH tiles exactly DOMAIN\n"
    "  mesh DOMAIN -o OUT [--size H] [--grading G] [--gamma G] [--algorithm front|delaunay]\n"
    "       [--certificate C.json] [--svg PICTURE.svg] [--save-domain D.poly]\n"
    "       [--no-improve] [--min-angle A] [--max-steiner N] [--quiet] [--convex-hull] [--radius-edge R]\n"
    "       [--refine-surface]\n"
    "                       mesh a 2D domain (.poly, or builtin:plate, builtin:square,\n"
    "                       builtin:two-holes) with triangles; the mesh is certified against\n"
    "                       the domain before anything is written (OUT: .mesh .msh .vtu .node)\n"
    "  check-surface SURFACE\n"
    "                       validate a closed triangulated surface exactly (.mesh .off .stl\n"
    "                       .poly .smesh): counts, or every problem by triangle\n"
    "  domain SCRIPT -o OUT.poly\n"
    "                       constructive geometry: rectangles, discs and polygons combined\n"
    "                       by union, difference, intersection (docs/domains.md)\n"
    "  fuzz TARGET [--seconds S | --cases N] [--seed K] [--jobs J] [--keep-going]\n"
    "       [--report R.json] [--out DIR] | --list | --replay FILE\n"
    "                       a fuzzing campaign against exact oracles: cases/s and progress,\n"
    "                       a reproducer file per finding (fuzz/README.md)\n"
    "  --help, -h           this text; COMMAND --help: that command's options and defaults\n"
    "  --version            the version\n"
    "\n"
    "predicates input, one query per line (numbers: decimal or C99 hex float, e.g. 0x1.8p-3,\n"
    "parsed exactly; nan, inf and out-of-range values like 1e400 are refused):\n"
    "  orient2d  ax ay bx by cx cy                     -> -1 | 0 | 1\n"
    "  orient3d  a b c d        (4 points x y z)       -> -1 | 0 | 1\n"
    "  incircle  a b c d        (4 points x y)         -> -1 | 0 | 1\n"
    "  insphere  a b c d e      (5 points x y z)       -> -1 | 0 | 1\n"
    "  seg_seg2d s0 s1 t0 t1    (2D segment, segment)  -> intersect | disjoint\n"
    "  tri_seg2d t0 t1 t2 s0 s1 (2D triangle, segment) -> intersect | disjoint\n"
    "  tri_seg3d t0 t1 t2 s0 s1 (3D triangle, segment) -> intersect | disjoint\n"
    "  tet_tri   a b c d t0 t1 t2 (3D)                 -> intersect | disjoint\n"
    "  tri_tri3d t0 t1 t2 u0 u1 u2 (3D)                -> intersect | disjoint\n"
    "modes: exact = exact signs; filter = the floating-point filter only, `?` when uncertain,\n"
    "  and the conservative intersection tests (they err only towards `intersect`);\n"
    "  sos = symbolically perturbed signs (0 only for repeated points), exact intersection.\n"
    "Points of one line with identical coordinates are the same vertex.\n"
    "Blank lines and `#` comments are skipped. A malformed line prints `error: line N: why`\n"
    "on stderr and nothing on stdout; processing continues.\n"
    "\n"
    "exit status: 0 success; 1 some input line was rejected (predicates), the demo found a\n"
    "disagreement, check found the mesh invalid, mesh found the domain invalid, or\n"
    "check-surface found the surface invalid; 2 usage\n"
    "error or unreadable input; 3 internal error (a generated mesh failed its certificate);\n"
    "4 mesh written but --min-angle not met (counted on standard error).\n"
    "fuzz: 0 no finding, 1 a finding (reproducer written), 2 usage error.\n";

int usage_error(const char* fmt, const char* arg) {
  std::fputs("error: ", stderr);
  std::fprintf(stderr, fmt, arg);
  std::fputs(" (see certimesh --help)\n", stderr);
  return 2;
}

// A positive finite number, or nullopt.
std::optional<double> positive_number(const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value > 0.0) || !std::isfinite(value)) return std::nullopt;
  return value;
}

// A finite number >= 0, or nullopt.
std::optional<double> non_negative_number(const char* text) {
  if (std::strcmp(text, "0") == 0) return 0.0;
  return positive_number(text);
}

int parse_and_run_mesh(int argc, char** argv) {
  certimesh::cli::MeshOptions options;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const bool has_value = i + 1 < argc;
    if ((arg == "-o" || arg == "--output") && has_value) {
      options.output = argv[++i];
    } else if (arg == "--size" && has_value) {
      const auto h = positive_number(argv[++i]);
      if (!h) return usage_error("mesh: --size needs a positive number, got '%s'", argv[i]);
      options.size = *h;
    } else if (arg == "--gamma" && has_value) {
      const auto g = positive_number(argv[++i]);
      if (!g || *g < 1.0) return usage_error("mesh: --gamma needs a number >= 1, got '%s'", argv[i]);
      options.gamma = *g;
    } else if (arg == "--grading" && has_value) {
      const auto g = non_negative_number(argv[++i]);
      if (!g) return usage_error("mesh: --grading needs a number >= 0, got '%s'", argv[i]);
      options.grading = *g;
    } else if (arg == "--algorithm" && has_value) {
      const std::string_view a = argv[++i];
      if (a != "front" && a != "delaunay") return usage_error("mesh: --algorithm is front or delaunay, got '%s'", argv[i]);
      options.delaunay = a == "delaunay";
    } else if (arg == "--certificate" && has_value) {
      options.certificate = argv[++i];
    } else if (arg == "--svg" && has_value) {
      options.svg = argv[++i];
    } else if (arg == "--save-domain" && has_value) {
      options.save_domain = argv[++i];
    } else if (arg == "--min-angle" && has_value) {
      const auto a = positive_number(argv[++i]);
      if (!a || *a >= 60.0) return usage_error("mesh: --min-angle needs degrees in (0, 60), got '%s'", argv[i]);
      options.min_angle = *a;
    } else if (arg == "--max-steiner" && has_value) {
      const auto n = positive_number(argv[++i]);
      if (!n || *n != std::floor(*n) || *n > 4e9) return usage_error("mesh: --max-steiner needs a whole number in [1, 4e9], got '%s'", argv[i]);
      options.max_steiner = static_cast<std::uint64_t>(*n);
    } else if (arg == "--radius-edge" && has_value) {
      const auto r = positive_number(argv[++i]);
      if (!r || *r < 1.0) return usage_error("mesh: --radius-edge needs a number >= 1, got '%s'", argv[i]);
      options.radius_edge = *r;
    } else if (arg == "--no-improve") {
      options.improve = false;
    } else if (arg == "--quiet") {
      options.quiet = true;
    } else if (arg == "--refine-surface") {
      options.refine_surface = true;
    } else if (arg == "--convex-hull") {
      options.convex_hull = true;
    } else if (!arg.starts_with("-") && options.domain.empty()) {
      options.domain = argv[i];
    } else {
      return usage_error("mesh: unexpected argument '%s'", argv[i]);
    }
  }
  if (options.domain.empty()) return usage_error("mesh needs a DOMAIN (.poly or builtin:plate)%s", "");
  if (options.output.empty()) return usage_error("mesh needs -o OUT%s", "");
  return certimesh::cli::run_mesh(options);
}

// `certimesh COMMAND ... --help ...`: anywhere after the command, as most tools accept it.
bool asks_for_help(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") return true;
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(kHelp, stderr);
    return 2;
  }
  const std::string_view command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (const std::string help = certimesh::cli::command_help(command); !help.empty() && asks_for_help(argc, argv)) {
    std::fputs(help.c_str(), stdout);
    return 0;
  }
  if (command == "--version") {
    std::printf("certimesh %s\n", CERTIMESH_VERSION);
    return 0;
  }
  if (command == "demo") {
    if (argc > 2) return usage_error("demo takes no arguments, got '%s'", argv[2]);
    return certimesh::cli::run_demo();
  }
  if (command == "predicates") {
    certimesh::cli::BatchOptions options;
    for (int i = 2; i < argc; ++i) {
      const std::string_view arg = argv[i];
      std::string_view value;
      if (arg == "--mode" && i + 1 < argc) {
        value = argv[++i];
      } else if (arg.starts_with("--mode=")) {
        value = arg.substr(7);
      } else if (arg == "--line-buffered") {
        options.line_buffered = true;
        continue;
      } else {
        return usage_error("predicates: unknown option '%s'", argv[i]);
      }
      if (value == "exact") {
        options.mode = certimesh::cli::BatchMode::exact;
      } else if (value == "filter") {
        options.mode = certimesh::cli::BatchMode::filter;
      } else if (value == "sos") {
        options.mode = certimesh::cli::BatchMode::sos;
      } else {
        return usage_error("predicates: --mode must be exact, filter or sos, got '%s'",
                           std::string(value).c_str());
      }
    }
    return certimesh::cli::run_batch(options);
  }
  if (command == "convert") {
    if (argc != 4) return usage_error("convert takes IN and OUT, got %s", argc < 4 ? "fewer" : "more");
    return certimesh::cli::run_convert(argv[2], argv[3]);
  }
  if (command == "check") {
    certimesh::cli::CheckOptions options;
    for (int i = 2; i < argc; ++i) {
      const std::string_view arg = argv[i];
      if (arg == "--domain" && i + 1 < argc) {
        options.domain = argv[++i];
      } else if (arg == "--certificate" && i + 1 < argc) {
        options.certificate = argv[++i];
      } else if (arg == "--boundary-tolerance" && i + 1 < argc) {
        if (!certimesh::cli::parse_boundary_tolerance(argv[++i], options.boundary_tolerance))
          return usage_error("check: --boundary-tolerance takes a positive distance or a count of ulps (4ulp), got '%s'", argv[i]);
      } else if (!arg.starts_with("--") && options.mesh.empty()) {
        options.mesh = argv[i];
      } else {
        return usage_error("check: unexpected argument '%s'", argv[i]);
      }
    }
    if (options.mesh.empty()) return usage_error("check needs a MESH file%s", "");
    return certimesh::cli::run_check(options);
  }
  if (command == "mesh") return parse_and_run_mesh(argc, argv);
  if (command == "fuzz") return certimesh::cli::parse_and_run_fuzz(argc, argv);
  if (command == "check-surface") {
    if (argc != 3 || std::string_view(argv[2]).starts_with("-")) return usage_error("check-surface takes one SURFACE file%s", "");
    return certimesh::cli::run_check_surface(argv[2]);
  }
  if (command == "domain") {
    if (argc == 5 && std::string_view(argv[3]) == "-o") return certimesh::cli::run_domain(argv[2], argv[4]);
    return usage_error("domain takes SCRIPT -o OUT.poly%s", "");
  }
  return usage_error("unknown command '%s'", argv[1]);
}
