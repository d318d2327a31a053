// PLACEHOLDER while the checker is being written (issue 4): refuses every mesh.
#include "certimesh/certificate/check_mesh.h"

namespace certimesh::certificate {

std::string_view defect_name(Defect) { return "not_implemented"; }

Report check_mesh(const io::MeshData&, const io::MeshData*) {
  Report report;
  report.finding.message = "the certificate is not implemented yet";
  return report;
}

std::string certificate_json(const Report&, const std::string&) { return "{}"; }

}  // namespace certimesh::certificate
