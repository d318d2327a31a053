#include "certimesh/fuzz/campaign/mesh2d_target.h"

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/fuzz/campaign/case_seed.h"
#include "certimesh/fuzz/campaign/named_target.h"
#include "certimesh/fuzz/planar_domains.h"
#include "certimesh/fuzz/recipes.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "payload_text.h"

namespace certimesh::fuzz::campaign {

namespace {

using generators::MeshAlgorithm2;
using generators::PlanarDomain;

io::MeshData certimesh_mesh(const PlanarDomain& domain, MeshAlgorithm2 algorithm) {
  generators::MeshDomainOptions2 options;
  options.algorithm = algorithm;
  return generators::mesh_domain_2(domain, options).mesh;
}

PlanarDomain scaled(PlanarDomain d, int j) {
  for (auto& p : d.points) p = {std::ldexp(p.x, j), std::ldexp(p.y, j)};
  for (auto& p : d.holes) p = {std::ldexp(p.x, j), std::ldexp(p.y, j)};
  for (auto& r : d.regions) r.point = {std::ldexp(r.point.x, j), std::ldexp(r.point.y, j)};
  return d;
}

std::string payload_of(const PlanarDomain& d, MeshAlgorithm2 algorithm, int j) {
  std::string p = algorithm == MeshAlgorithm2::delaunay ? "delaunay " : "front ";
  p += std::to_string(j);
  const auto number = [&p](const std::string& word) {
    p.push_back(' ');
    p += word;
  };
  number(std::to_string(d.points.size()));
  for (const auto& q : d.points) number(hex_double(q.x)), number(hex_double(q.y));
  number(std::to_string(d.segments.size()));
  for (const auto& s : d.segments) number(std::to_string(s.a)), number(std::to_string(s.b)), number(std::to_string(s.label));
  number(std::to_string(d.holes.size()));
  for (const auto& q : d.holes) number(hex_double(q.x)), number(hex_double(q.y));
  return p;
}

std::optional<Finding> check(const Mesh2dKernel& kernel, const PlanarDomain& d, MeshAlgorithm2 algorithm, int j) {
  const std::string payload = payload_of(d, algorithm, j);
  const auto found = [&](const std::string& what) { return Finding{"mesh2d: " + what, payload}; };
  const io::MeshData domain = generators::to_mesh_data(d);
  io::MeshData mesh, twin;
  try {
    mesh = kernel.mesh(d, algorithm);
  } catch (const std::exception& e) {
    return found(std::string("the pipeline throws on a valid domain: ") + e.what());
  }
  const auto report = certificate::check_mesh(mesh, &domain);
  if (!report.valid) return found("the certificate refuses the mesh: " + report.finding.message);
  try {
    twin = kernel.mesh(scaled(d, j), algorithm);
  } catch (const std::exception& e) {
    return found(std::string("the pipeline throws on the domain scaled by 2^j: ") + e.what());
  }
  if (twin.triangles != mesh.triangles || twin.triangle_labels != mesh.triangle_labels || twin.segments != mesh.segments ||
      twin.segment_labels != mesh.segment_labels || twin.coordinates.size() != mesh.coordinates.size())
    return found("scaling the domain by 2^j changes the mesh's connectivity or labels");
  for (std::size_t i = 0; i < mesh.coordinates.size(); ++i)
    if (twin.coordinates[i] != std::ldexp(mesh.coordinates[i], j))
      return found("scaling the domain by 2^j does not scale coordinate " + std::to_string(i) + " by 2^j");
  return std::nullopt;
}

class Mesh2dTarget final : public KernelTarget<Mesh2dKernel> {
 public:
  using KernelTarget::KernelTarget;
  std::optional<Finding> run_case(std::uint64_t seed) const override {
    SplitMixSource s(seed);
    const auto family = static_cast<DomainFamily>(s.below(kDomainFamilies));
    const std::uint64_t domain_seed = s.bits();
    const std::size_t vertices = 3 + s.below(14);
    const int exponent = s.below(8) == 0 ? static_cast<int>(draw_int(s, -900, 900)) : static_cast<int>(draw_int(s, -35, 45));
    const auto algorithm = s.below(2) ? MeshAlgorithm2::delaunay : MeshAlgorithm2::advancing_front;
    const int j = static_cast<int>(draw_nonzero(s, 8));
    return check(kernel_, make_valid_domain(family, domain_seed, vertices, exponent).domain, algorithm, j);
  }
  std::optional<Finding> replay(std::string_view payload) const override {
    PayloadReader in(payload);
    const std::string algorithm = in.next_word();
    if (algorithm != "front" && algorithm != "delaunay") throw MalformedPayload("unknown algorithm '" + algorithm + "' (front, delaunay)");
    const auto count = [&](double hi) {
      const double v = in.next_double();
      if (!(v >= -hi && v <= hi) || v != std::floor(v)) throw MalformedPayload("expected an integer of at most " + std::to_string(hi));
      return static_cast<std::int64_t>(v);
    };
    const int j = static_cast<int>(count(64));
    PlanarDomain d;
    for (auto n = count(1e6); n > 0; --n) {
      const double x = in.next_double();
      d.points.push_back({x, in.next_double()});
    }
    for (auto n = count(1e6); n > 0; --n) {
      const auto a = static_cast<generators::DomainVertex>(count(4e9)), b = static_cast<generators::DomainVertex>(count(4e9));
      d.segments.push_back({a, b, static_cast<io::Label>(count(2e9))});
    }
    for (auto n = count(1e6); n > 0; --n) {
      const double x = in.next_double();
      d.holes.push_back({x, in.next_double()});
    }
    in.expect_end();
    return check(kernel_, d, algorithm == "delaunay" ? MeshAlgorithm2::delaunay : MeshAlgorithm2::advancing_front, j);
  }

};

}  // namespace

Mesh2dKernel certimesh_mesh2d_kernel() { return {certimesh_mesh}; }

std::unique_ptr<Target> make_mesh2d_target(const Mesh2dKernel& kernel, std::string name, std::string description) {
  return std::make_unique<Mesh2dTarget>(kernel, std::move(name), std::move(description));
}

std::unique_ptr<Target> make_mesh2d_target() {
  return make_mesh2d_target(certimesh_mesh2d_kernel(), "mesh2d",
                            "the 2D pipeline, both algorithms, on generated valid domains: the certificate accepts every "
                            "mesh, and scaling the domain by 2^j scales the mesh bit for bit");
}

}  // namespace certimesh::fuzz::campaign
