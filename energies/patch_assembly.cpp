#include "bezierpde/energies/patch_assembly.h"

#include <string>

#include "bezierpde/core/errors.h"

namespace bpde {

Eigen::MatrixX3d patch_points(const PatchAssembly& a, int p, const Eigen::MatrixX3d& P) {
  if (P.rows() != a.size)
    throw SizeError("patch assembly: " + std::to_string(P.rows()) + " points given, the complex has " +
                    std::to_string(a.size));
  return P(a.maps[static_cast<std::size_t>(p)], Eigen::all);
}

std::vector<int> positions(const PatchAssembly& a, const std::vector<int>& idx) {
  std::vector<int> where(static_cast<std::size_t>(a.size), -1);
  for (std::size_t i = 0; i < idx.size(); ++i) {
    if (idx[i] < 0 || idx[i] >= a.size) throw SizeError("patch assembly: point index out of range");
    where[static_cast<std::size_t>(idx[i])] = static_cast<int>(i);
  }
  return where;
}

void local_rows(const PatchAssembly& a, int p, const std::vector<int>& where, std::vector<int>& local,
                std::vector<int>& pos) {
  local.clear();
  pos.clear();
  const std::vector<int>& map = a.maps[static_cast<std::size_t>(p)];
  for (std::size_t r = 0; r < map.size(); ++r) {
    const int at = where[static_cast<std::size_t>(map[r])];
    if (at < 0) continue;
    local.push_back(static_cast<int>(r));
    pos.push_back(at);
  }
}

Eigen::MatrixX3d assembled_rows(const PatchAssembly& a, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                                const PatchRowsFn& rows) {
  const std::vector<int> where = positions(a, idx);
  Eigen::MatrixX3d G = Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(idx.size()), 3);
  std::vector<int> local, pos;
  for (int p = 0; p < a.patches(); ++p) {
    local_rows(a, p, where, local, pos);
    if (local.empty()) continue;
    const Eigen::MatrixX3d Gp = rows(patch_points(a, p, P), local);
    for (std::size_t r = 0; r < local.size(); ++r) G.row(pos[r]) += Gp.row(static_cast<Eigen::Index>(r));
  }
  return G;
}

std::vector<Eigen::Triplet<double>> assembled_hessian_triplets(const PatchAssembly& a, const Eigen::MatrixX3d& P,
                                                               const std::vector<int>& idx,
                                                               const PatchHessianFn& hess) {
  const std::vector<int> where = positions(a, idx);
  std::vector<Eigen::Triplet<double>> t;
  std::vector<int> local, pos;
  for (int p = 0; p < a.patches(); ++p) {
    local_rows(a, p, where, local, pos);
    if (local.empty()) continue;
    const Eigen::MatrixXd Hp = hess(patch_points(a, p, P), local);
    const Eigen::Index kp = static_cast<Eigen::Index>(local.size());
    t.reserve(t.size() + static_cast<std::size_t>(9 * kp * kp));
    for (Eigen::Index b = 0; b < kp; ++b)
      for (Eigen::Index i = 0; i < kp; ++i)
        for (int s = 0; s < 3; ++s)
          for (int r = 0; r < 3; ++r) {
            const double v = Hp(3 * i + r, 3 * b + s);
            if (v != 0.0) t.emplace_back(3 * pos[static_cast<std::size_t>(i)] + r, 3 * pos[static_cast<std::size_t>(b)] + s, v);
          }
  }
  return t;
}

Eigen::SparseMatrix<double> assembled_hessian_sparse(const PatchAssembly& a, const Eigen::MatrixX3d& P,
                                                     const std::vector<int>& idx, const PatchHessianFn& hess) {
  const auto t = assembled_hessian_triplets(a, P, idx, hess);
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(idx.size());
  Eigen::SparseMatrix<double> S(n, n);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

Eigen::MatrixXd assembled_hessian_dense(const PatchAssembly& a, const Eigen::MatrixX3d& P,
                                        const std::vector<int>& idx, const PatchHessianFn& hess) {
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(idx.size());
  Eigen::MatrixXd Hs = Eigen::MatrixXd::Zero(n, n);
  for (const auto& e : assembled_hessian_triplets(a, P, idx, hess)) Hs(e.row(), e.col()) += e.value();
  return Hs;
}

Eigen::MatrixXd assembled_matrix(const PatchAssembly& a, const Eigen::MatrixXd& patch_matrix) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(a.size, a.size);
  for (const std::vector<int>& map : a.maps)
    for (std::size_t i = 0; i < map.size(); ++i)
      for (std::size_t j = 0; j < map.size(); ++j)
        M(map[i], map[j]) += patch_matrix(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  return M;
}

}  // namespace bpde
