// `certimesh COMMAND --help`: each subcommand's usage, every option with its default. The
// defaults are read from the option structs (cli.h), so the text cannot drift from them.
#include <cstdio>
#include <string>
#include <string_view>

#include "certimesh/fuzz/campaign/campaign.h"
#include "cli.h"

namespace certimesh::cli {

namespace {

std::string format(const char* fmt, double value) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, fmt, value);
  return buffer;
}

std::string mesh_help() {
  const MeshOptions d;
  return "usage: certimesh mesh DOMAIN -o OUT [options]\n"
         "\n"
         "Meshes a 2D domain with triangles, certifies the mesh against the domain with the\n"
         "independent checker, and writes it only if the certificate holds.\n"
         "\n"
         "  DOMAIN               a .poly file, or builtin:plate, builtin:square, builtin:two-holes;\n"
         "                       a .node file of 2D points (no segments) is meshed as the\n"
         "                       Delaunay triangulation of its convex hull, every point a vertex;\n"
         "                       a .node of 3D points as the Delaunay tetrahedralization of its\n"
         "                       convex hull (as TetGen does), every point a vertex, certified as\n"
         "                       a mesh of positive tetrahedra; refined inside (never on the hull)\n"
         "                       when --size or --radius-edge is given; --svg draws its cut by\n"
         "                       the plane through the middle of the z range, by quality.\n"
         "                       A closed surface (.off, .stl, .mesh triangles, TetGen\n"
         "                       .smesh/.poly) is validated exactly (open, non-manifold,\n"
         "                       degenerate, self-intersecting: refused naming the triangles;\n"
         "                       docs/surface_input.md), its solid (winding number not zero:\n"
         "                       an inward inner shell is a cavity) tetrahedralized with the\n"
         "                       surface recovered exactly -- every input triangle a boundary\n"
         "                       face, no Steiner point on it -- then refined (radius-edge 2,\n"
         "                       sizes from the surface's edges, or --size), and certified\n"
         "                       against the surface before it is written.\n"
         "                       A .poly is read as Triangle reads it: vertices on no segment\n"
         "                       are mesh vertices (dropped when outside the domain), segments\n"
         "                       inside the domain are mesh edges, segments with the domain on\n"
         "                       neither side are eaten by the holes, regional attributes are\n"
         "                       real numbers and a region's maximum area is a bound on every\n"
         "                       triangle in it, markers become labels; a hole point outside\n"
         "                       every face is refused\n"
         "  -o, --output OUT     the mesh (required); format by extension: " +
         std::string(kMeshOutputExtensions) +
         "\n"
         "  --size H             largest edge length (default: " +
         (d.size > 0 ? format("%g", d.size)
                     : format("%g times the diagonal of the\n                       domain's bounding box", generators::default_maximum_fraction)) +
         ")\n"
         "  --grading G          the size follows the boundary's local feature size (each\n"
         "                       domain point's distance to its nearest other point or segment,\n"
         "                       its own segments' lengths included) and grows away from it by\n"
         "                       at most G per unit of distance, up to --size; 0: --size\n"
         "                       everywhere, or without --size growth by --gamma from the\n"
         "                       boundary's own segments (default: " +
         format("%g", d.grading) +
         ")\n"
         "  --gamma G            growth factor per front layer, >= 1: with a size, how fast the\n"
         "                       front may coarsen towards it; with --grading 0 and no --size,\n"
         "                       the size itself (default: " +
         format("%g", d.gamma) +
         ", no limit)\n"
         "  --algorithm A        front (advancing front) or delaunay (default: " +
         (d.delaunay ? "delaunay" : "front") +
         ")\n"
         "  --certificate C.json also write the certificate (default: not written)\n"
         "  --svg PICTURE.svg    also write a picture of the mesh; of a 3D mesh, the tetrahedra\n"
         "                       cut by z = the middle of its z range, coloured by quality\n"
         "                       (red 0 to green 1) (default: not written)\n"
         "  --save-domain D.poly also write the domain, for `certimesh check --domain`\n"
         "                       (default: not written)\n"
         "  --no-improve         skip the quality improvement: in 2D the local\n"
         "                       modifications, in 3D the sliver removal after refinement\n"
         "                       (edge removals, 2-3 flips, node shifts; the surface is kept\n"
         "                       exactly) (default: improve " +
         (d.improve ? "on" : "off") +
         ")\n"
         "  --min-angle A        every triangle's smallest angle at least A degrees, 0 < A < 60\n"
         "                       (Triangle's -q A; default: " +
         (d.min_angle > 0 ? format("%g", d.min_angle) : std::string("no guarantee")) +
         "). Delaunay refinement\n"
         "                       with segment splitting (Ruppert, Shewchuk; concentric shells)\n"
         "                       runs last: with --algorithm delaunay it is the refinement (and\n"
         "                       meets --size); with the front, the front and the improvement\n"
         "                       place the vertices, then the constrained Delaunay\n"
         "                       triangulation of them is refined, so nothing after it lowers\n"
         "                       an angle. Proven to end for A <= 20.7 when no input angle is\n"
         "                       below 60; in practice up to about 33 (beyond about 34 it\n"
         "                       rarely ends: the cap stops it). Exempt: a triangle whose\n"
         "                       shortest edge joins two Steiner points on two segments that\n"
         "                       meet at an input vertex at less than 60 degrees, equally far\n"
         "                       from it (within 0.1 % in squared length): the input angle\n"
         "                       forces it. Angles are measured on the written coordinates.\n"
         "                       Refused for a .node point set\n"
         "  --max-steiner N      Steiner points --min-angle (2D) or the refinement (3D) may add\n"
         "                       before it stops and says so (exit status 4) (default: " +
         std::to_string(d.max_steiner) +
         ")\n"
         "  --convex-hull        add the convex hull of all the points as outer boundary, as\n"
         "                       Triangle's -c (default: " +
         (d.convex_hull ? "on" : "off") +
         "); --save-domain then writes that domain\n"
         "  --radius-edge R      3D: refine every tetrahedron whose circumradius exceeds R times\n"
         "                       its shortest edge, R >= 1, where the circumcentre may go (not\n"
         "                       outside, not next to a boundary face: the boundary is kept)\n"
         "                       (default: 2 for a surface; a 3D .node point set is its\n"
         "                       Delaunay tetrahedralization unless --size or --radius-edge\n"
         "                       is given, as tetgen without -q; with --size alone R is 2)\n"
         "  --refine-surface     3D: Steiner points of the boundary recovery may stay on the\n"
         "                       surface, each the rounding of an exact point of its edge or\n"
         "                       triangle (default: off: none on the surface)\n"
         "  --quiet              no progress on a terminal, only the summary (default: " +
         (d.quiet ? "on" : "off") +
         ")\n"
         "  -h, --help           this text\n"
         "\n"
         "exit status: 0 written; 1 invalid domain; 2 usage error or unreadable input;\n"
         "3 internal error (the mesh failed its certificate; nothing written); 4 written,\n"
         "but --min-angle not met (the cap was reached, or no admissible Steiner point was\n"
         "left; the triangles below it are counted on standard error), or a 3D refinement\n"
         "stopped at --max-steiner.\n";
}

std::string check_help() {
  return "usage: certimesh check MESH [--domain DOMAIN] [--certificate OUT.json]\n"
         "                       [--boundary-tolerance D]\n"
         "\n"
         "Certifies MESH exactly: oriented elements, conforming facets, an embedded boundary,\n"
         "a single cover. Pinches are valid (parts sharing a corner, a hole touching the\n"
         "outer loop, solids sharing a vertex or an edge). A .node MESH reads its elements\n"
         "from the .ele beside it.\n"
         "\n"
         "  MESH                 " +
         std::string(kMeshInputExtensions) +
         "\n"
         "  --domain DOMAIN      also check that MESH tiles exactly DOMAIN (.poly in 2D; in\n"
         "                       3D a TetGen .poly/.smesh -- planar polygonal facets, facet\n"
         "                       holes, hole points, region attributes checked against the\n"
         "                       tetrahedron labels -- or a closed surface mesh) (default: no\n"
         "                       domain)\n"
         "  --certificate OUT.json  write the certificate as JSON (default: not written)\n"
         "  --boundary-tolerance D  accept mesh boundary vertices within D of their domain\n"
         "                       segment / triangle in each coordinate (D a distance, e.g.\n"
         "                       1e-12, or a count of ulps, e.g. 4ulp), as meshes written by\n"
         "                       Triangle or Gmsh need; domain vertices stay exact (default:\n"
         "                       the exact rule, half an ulp per coordinate)\n"
         "  -h, --help           this text\n"
         "\n"
         "exit status: 0 valid; 1 invalid (the first defect named); 2 usage error or\n"
         "unreadable input (a missing file is named).\n";
}

std::string check_surface_help() {
  return "usage: certimesh check-surface SURFACE\n"
         "\n"
         "Validates a closed triangulated surface, the input of 3D meshing, exactly (every\n"
         "decision an exact predicate; docs/surface_input.md):\n"
         "  SURFACE              .mesh (its Triangles), .off (0-based; polygons must be planar\n"
         "                       and simple), .stl (ASCII or binary, told apart by size; corners\n"
         "                       with equal coordinates welded), .poly/.smesh (TetGen: one\n"
         "                       planar simple polygon per facet; orientation ignored, every\n"
         "                       shell turned outward)\n"
         "  -h, --help           this text\n"
         "\n"
         "Refused, each problem on standard error as `error: SURFACE: ...` naming the triangles\n"
         "(0-based) and their corners: duplicate vertices, zero-area or repeated triangles, open\n"
         "edges, non-manifold edges (3 or more triangles that do not alternate around the edge),\n"
         "two triangles running their common edge the same way, and every pair of triangles\n"
         "meeting beyond their shared vertices (touching included; at most 10 listed, all\n"
         "counted). A valid surface prints its counts: vertices, triangles, shells, and of the\n"
         "shells the solids (winding number 0 outside), cavities (0 inside) and interfaces. The\n"
         "solid is where the winding number is non-zero: an inward shell inside an outward one\n"
         "is a cavity; a lone shell is a solid whichever way it is oriented. TetGen hole and\n"
         "region points are counted and passed on (in a .poly/.smesh every shell is turned\n"
         "outward: nested shells are interfaces, cavities come from hole points).\n"
         "\n"
         "exit status: 0 valid; 1 invalid surface; 2 usage error or unreadable file.\n";
}

std::string convert_help() {
  return "usage: certimesh convert IN OUT\n"
         "\n"
         "Converts a mesh between formats, each chosen by its file's extension:\n"
         "  IN, OUT              " +
         std::string(kMeshInputExtensions) +
         "\n"
         "                       (.node/.ele/.face/.poly: Triangle, TetGen; .mesh: Medit;\n"
         "                       .msh: Gmsh 4.1 ASCII; .vtu: VTK XML, for ParaView)\n"
         "                       IN may also be a surface .off or .stl (read only; STL\n"
         "                       corners with equal coordinates become one vertex)\n"
         "  -h, --help           this text\n"
         "\n"
         "exit status: 0 written; 2 usage error, unsupported extension, unreadable IN or\n"
         "unwritable OUT (nothing written).\n";
}

std::string predicates_help() {
  const BatchOptions d;
  const char* mode = d.mode == BatchMode::exact ? "exact" : d.mode == BatchMode::filter ? "filter" : "sos";
  return std::string("usage: certimesh predicates [--mode exact|filter|sos] [--line-buffered]\n"
                     "\n"
                     "Batch predicates: one query per stdin line, one answer per stdout line\n"
                     "(the query syntax is in `certimesh --help`).\n"
                     "\n"
                     "  --mode M             exact, filter or sos; also --mode=M (default: ") +
         mode +
         ")\n"
         "  --line-buffered      flush after every answer, for co-processes (default: " +
         (d.line_buffered ? "on" : "off") +
         ")\n"
         "  -h, --help           this text\n"
         "\n"
         "exit status: 0 every line answered; 1 some line rejected; 2 usage error.\n";
}

std::string domain_help() {
  return "usage: certimesh domain SCRIPT -o OUT.poly\n"
         "\n"
         "Constructive geometry: rectangles, discs and polygons combined by union,\n"
         "difference and intersection (docs/domains.md), written as a .poly domain.\n"
         "\n"
         "  SCRIPT               the domain script\n"
         "  -o OUT.poly          the domain (required)\n"
         "  -h, --help           this text\n"
         "\n"
         "exit status: 0 written; 1 bad script or invalid domain; 2 usage error, unreadable\n"
         "script or unwritable output.\n";
}

std::string demo_help() {
  return "usage: certimesh demo\n"
         "\n"
         "Naive floating point against certimesh on the classroom robustness examples; every\n"
         "answer is re-checked with GMP. No options.\n"
         "\n"
         "  -h, --help           this text\n"
         "\n"
         "exit status: 0 every certimesh answer agrees with GMP; 1 a disagreement.\n";
}

}  // namespace

std::string fuzz_help() {
  const FuzzOptions d;
  return "usage: certimesh fuzz TARGET [--seconds S | --cases N] [--seed K] [--jobs J]\n"
         "                      [--keep-going] [--report R.json] [--out DIR]\n"
         "       certimesh fuzz --list\n"
         "       certimesh fuzz --replay FILE\n"
         "\n"
         "Runs TARGET's cases 0, 1, 2, ... against exact oracles that share no code with what\n"
         "they check; case i draws its input from splitmix64(K ^ splitmix64(i)), so a seed and\n"
         "a budget of cases give the same cases, and the same first finding, for any --jobs.\n"
         "Progress and cases/s go to stderr every " + format("%g", d.progress_interval) + " s; the summary to stdout.\n"
         "\n"
         "  TARGET               one of `certimesh fuzz --list`\n"
         "  --seconds S          wall-clock budget (default: " + format("%g", d.seconds) + " s)\n"
         "  --cases N            a budget of N cases instead of seconds (default: none)\n"
         "  --seed K             the campaign seed, decimal or 0x hex (default: " + std::to_string(d.seed) + ")\n"
         "  --jobs J             threads (default: " + std::to_string(d.jobs) + ")\n"
         "  --keep-going         run the whole budget and write every finding, the lowest " +
         std::to_string(fuzz::campaign::CampaignOptions{}.max_findings) + "\n"
         "                       kept (default: stop at the first)\n"
         "  --report R.json      a JSON record: target, commit, seed, jobs, cases, seconds,\n"
         "                       cases/s, findings (default: none)\n"
         "  --out DIR            where reproducers go, as TARGET-seedK-caseI.repro (default: " + d.out + ")\n"
         "  --list               the targets, with what each checks\n"
         "  --replay FILE        re-run a reproducer's input, and its case seed through this\n"
         "                       build's generators\n"
         "\n"
         "exit status: 0 no finding (replay: the input passes), 1 a finding, its reproducer\n"
         "written (replay: the input still fails), 2 usage error or unreadable/unwritable file.\n";
}

std::string command_help(std::string_view command) {
  if (command == "fuzz") return fuzz_help();
  if (command == "mesh") return mesh_help();
  if (command == "check") return check_help();
  if (command == "convert") return convert_help();
  if (command == "check-surface") return check_surface_help();
  if (command == "predicates") return predicates_help();
  if (command == "domain") return domain_help();
  if (command == "demo") return demo_help();
  return {};
}

}  // namespace certimesh::cli
