// Placeholder: the CGAL implementation replaces this file.
#include "checks/mesh_checks.h"

#include "core/errors.h"

namespace bpde {

MeshCheckReport check_mesh(const std::vector<double>&, const std::vector<int>&) {
  throw UnsupportedProblem("mesh checks are not available in this build yet");
}

}  // namespace bpde
