// The certimesh command-line tool: subcommand entry points. The library never prints;
// everything the user sees is rendered here.
#pragma once

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/size_policy.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace certimesh::cli {

/// The extensions each command accepts, space-separated, as the help and the errors print them.
inline constexpr const char* kMeshOutputExtensions = ".mesh .msh .vtu .node .ele";
inline constexpr const char* kMeshInputExtensions = ".node .ele .face .poly .mesh .msh .vtu";

/// `certimesh COMMAND --help`: the usage of COMMAND, every option with its default; empty
/// for an unknown command.
std::string command_help(std::string_view command);

/// True when `path`'s extension is one of `supported`; otherwise prints
/// `error: PATH: unsupported output extension '.x' (supported: ...)` and returns false. The
/// commands call it before any work, so a wrong name costs nothing and writes nothing.
bool output_extension_supported(const std::string& path, std::string_view supported);

enum class BatchMode { exact, filter, sos };

struct BatchOptions {
  BatchMode mode = BatchMode::exact;
  bool line_buffered = false;  // flush stdout after every answer (for co-processes)
};

/// `certimesh predicates`: reads predicate queries from stdin, one per line, and writes one
/// answer per query line to stdout. Returns 0 when every line was answered, 1 when at least
/// one line was rejected (each rejection is reported on stderr as `error: line N: why`).
int run_batch(const BatchOptions& options);

/// `certimesh convert IN OUT`: reads IN and writes OUT, formats chosen by extension.
/// Returns 0 on success, 2 when IN is unreadable or OUT cannot be written (`error: ...`).
int run_convert(const std::string& input, const std::string& output);

struct CheckOptions {
  std::string mesh;
  std::string domain;       // empty: no domain
  std::string certificate;  // empty: no JSON certificate written
  certificate::BoundaryTolerance boundary_tolerance;  // default: the exact rounding-box rule
};

/// Reads `--boundary-tolerance`'s value: a positive distance ("1e-12") or a count of ulps
/// ("4ulp", "4ulps"). False for anything else.
bool parse_boundary_tolerance(std::string_view text, certificate::BoundaryTolerance& out);

/// `certimesh check MESH [--domain D] [--certificate OUT.json] [--boundary-tolerance D]`: the
/// independent certificate.
/// Returns 0 valid, 1 invalid (first offending element or facet named), 2 unreadable input.
int run_check(const CheckOptions& options);

struct MeshOptions {
  std::string domain;        // a .poly file, or builtin:plate | builtin:square | builtin:two-holes
  std::string output;        // the mesh; format by extension (.mesh, .msh, .vtu, .node)
  std::string certificate;   // empty: no JSON certificate
  std::string svg;           // empty: no picture
  std::string save_domain;   // empty: the domain is not written (else as .poly, for check)
  double size = 0.0;         // --size H, the largest size; 0: a tenth of the domain's diagonal
  double gamma = 1.0;        // --gamma G, the front's growth factor per layer (1: no limit)
  double grading = generators::default_grading;  // --grading G; 0: no boundary-adapted size
  bool delaunay = false;     // --algorithm delaunay (default: front)
  bool improve = true;       // --no-improve turns the local-modification stage off
  bool quiet = false;        // --quiet: no progress, summary only
  double min_angle = 0.0;    // --min-angle A (degrees); 0: no angle guarantee
  std::uint64_t max_steiner = 4'000'000;  // --max-steiner N: the cap of the --min-angle refinement
  bool convex_hull = false;  // --convex-hull: the convex hull of the points as outer boundary (Triangle's -c)
  double radius_edge = 0.0;  // --radius-edge R (3D): 0 = unset (surfaces: 2; point sets: no refinement)
  bool refine_surface = false;  // --refine-surface (3D): boundary Steiner points allowed
};

/// `certimesh mesh DOMAIN -o OUT ...`: meshes DOMAIN, certifies the mesh with the independent
/// checker and writes it (and the certificate and picture when asked) only if it is valid.
/// Returns 0 written, 1 invalid domain (every problem named), 2 unreadable input or bad
/// option, 3 internal error (a mesh that fails its certificate; nothing written), 4 written
/// but --min-angle not met (the Steiner cap stopped the refinement; the triangles are counted).
int run_mesh(const MeshOptions& options);

/// `certimesh domain SCRIPT -o OUT.poly`: constructive geometry of planar domains
/// (docs/domains.md). Returns 0 written, 1 bad script or invalid result, 2 unreadable script
/// or unwritable output.
int run_domain(const std::string& script_path, const std::string& output);

/// `certimesh check-surface SURFACE`: reads a closed surface (.mesh .off .stl .poly .smesh) and
/// validates it exactly (docs/surface_input.md). Returns 0 valid (counts printed), 1 invalid
/// (each problem on stderr as `error: SURFACE: ...`), 2 unreadable.
int run_check_surface(const std::string& path);

struct FuzzOptions {
  bool list = false;          // --list: the targets, one line each
  std::string replay;         // --replay FILE: re-run one reproducer
  std::string target;         // TARGET (certimesh fuzz --list)
  std::uint64_t cases = 0;    // --cases N; 0: the seconds budget
  double seconds = 60.0;      // --seconds S (ignored when --cases is given)
  std::uint64_t seed = 0;     // --seed K: case i draws from splitmix64(K ^ splitmix64(i))
  unsigned jobs = 1;          // --jobs J: threads
  bool keep_going = false;    // --keep-going: run the whole budget, every finding written
  std::string report;         // --report R.json; empty: none
  std::string out = ".";      // --out DIR: where the reproducers go
  double progress_interval = 10.0;  // seconds between progress lines on stderr
};

/// `certimesh fuzz ...` from the command line (argv[1] == "fuzz"). Returns 0 clean, 1 a
/// finding (its reproducer written) or a replay that still fails, 2 usage error or
/// unreadable/unwritable file (`error: ...`).
int parse_and_run_fuzz(int argc, char** argv);
int run_fuzz(const FuzzOptions& options);

/// `certimesh demo`: the classroom failures of naive floating point, and certimesh's answers.
int run_demo();

}  // namespace certimesh::cli
