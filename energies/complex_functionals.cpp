#include "bezierpde/energies/complex_functionals.h"

#include <algorithm>
#include <string>
#include <utility>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

int patch_count(PatchKind kind, int n) {
  return kind == PatchKind::triangular ? TriangularNet::count(n) : (n + 1) * (n + 1);
}

void check_fixed(const PatchComplex& c) {
  const int N = static_cast<int>(c.points.rows());
  for (std::size_t i = 0; i < c.fixed.size(); ++i) {
    if (c.fixed[i] < 0 || c.fixed[i] >= N) throw SizeError("complex: a fixed row is outside the points");
    if (i > 0 && c.fixed[i] <= c.fixed[i - 1]) throw SizeError("complex: the fixed rows must be sorted and unique");
  }
}

std::shared_ptr<const CmcFunctional> patch_functional(const PatchComplex& c) {
  const int n = c.patches.front().degree;
  return c.patches.front().kind == PatchKind::triangular ? CmcFunctional::cached_triangular(n)
                                                         : CmcFunctional::cached_tensor(n, n);
}

}  // namespace

std::shared_ptr<const PatchAssembly> patch_assembly(const PatchComplex& c) {
  if (c.patches.empty()) throw ParameterError("complex: no patches");
  const PatchKind kind = c.patches.front().kind;
  const int n = c.patches.front().degree;
  if (n < 1 || n > kMaxDegree) throw DegreeError("complex: degree " + std::to_string(n) + " is outside 1..64");
  auto a = std::make_shared<PatchAssembly>();
  a->size = static_cast<int>(c.points.rows());
  a->patch_size = patch_count(kind, n);
  for (const ComplexPatch& p : c.patches) {
    if (p.kind != kind || p.degree != n) throw ParameterError("complex: the patches must share one kind and degree");
    if (static_cast<int>(p.points.size()) != a->patch_size) throw SizeError("complex: a patch lists the wrong number of points");
    for (int r : p.points)
      if (r < 0 || r >= a->size) throw SizeError("complex: a patch point is outside the points");
    a->maps.push_back(p.points);
  }
  check_fixed(c);
  return a;
}

std::vector<int> complex_free_rows(const PatchComplex& c) {
  check_fixed(c);
  std::vector<int> free;
  for (int r = 0; r < static_cast<int>(c.points.rows()); ++r)
    if (!std::binary_search(c.fixed.begin(), c.fixed.end(), r)) free.push_back(r);
  return free;
}

TriangularNet triangular_patch(const PatchComplex& c, int p) {
  const ComplexPatch& cp = c.patches.at(static_cast<std::size_t>(p));
  if (cp.kind != PatchKind::triangular) throw ParameterError("complex: the patch is not triangular");
  return TriangularNet(cp.degree, c.points(cp.points, Eigen::all));
}

TensorNet tensor_patch(const PatchComplex& c, int p) {
  const ComplexPatch& cp = c.patches.at(static_cast<std::size_t>(p));
  if (cp.kind != PatchKind::tensor) throw ParameterError("complex: the patch is not a tensor patch");
  return TensorNet(cp.degree, cp.degree, c.points(cp.points, Eigen::all));
}

std::shared_ptr<const CmcFunctional> complex_cmc_functional(const PatchComplex& c) {
  auto a = patch_assembly(c);
  return std::make_shared<const CmcFunctional>(CmcFunctional::assembled(patch_functional(c), std::move(a)));
}

std::shared_ptr<const AreaForm> complex_area_form(const PatchComplex& c, int q, int grading, int levels) {
  auto a = patch_assembly(c);
  const int n = c.patches.front().degree;
  auto patch = c.patches.front().kind == PatchKind::triangular ? AreaForm::cached_triangular(n, q, grading, levels)
                                                               : AreaForm::cached_tensor(n, n, q, grading, levels);
  return std::make_shared<const AreaForm>(AreaForm::assembled(std::move(patch), std::move(a)));
}

Eigen::SparseMatrix<double> dirichlet_hessian_sparse(const PatchComplex& c) {
  const auto f = patch_functional(c);
  return assembled_hessian_sparse(*patch_assembly(c), c.points, complex_free_rows(c),
                                  [&](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) {
                                    return f->hessian(Pp, 0.0, l);
                                  });
}

Eigen::SparseMatrix<double> volume_hessian_sparse(const PatchComplex& c) {
  const auto f = patch_functional(c);
  return assembled_hessian_sparse(*patch_assembly(c), c.points, complex_free_rows(c),
                                  [&](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) {
                                    return f->volume_form().hessian(Pp, l);
                                  });
}

Eigen::SparseMatrix<double> area_hessian_sparse(const PatchComplex& c, const AreaForm& patch_rule) {
  return assembled_hessian_sparse(*patch_assembly(c), c.points, complex_free_rows(c),
                                  [&](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) {
                                    return patch_rule.hessian(Pp, l);
                                  });
}

Eigen::VectorXd free_vector(const Eigen::MatrixX3d& G, const std::vector<int>& free) {
  Eigen::VectorXd y(3 * static_cast<Eigen::Index>(free.size()));
  for (std::size_t a = 0; a < free.size(); ++a) y.segment<3>(3 * static_cast<Eigen::Index>(a)) = G.row(free[a]).transpose();
  return y;
}

}  // namespace bpde
