// The assembled forms of energies/volume.h and energies/area_functional.h: sums of the patch's
// form over the patches of a PatchAssembly (energies/patch_assembly.h).
#include "bezierpde/core/eigen.h"
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/energies/patch_assembly.h"
#include "bezierpde/energies/volume.h"

namespace bpde {
namespace {

void check_assembly(const PatchAssembly& a, int patch_size, const char* what) {
  if (a.patch_size != patch_size)
    throw SizeError(std::string(what) + ": the assembly's patches have " + std::to_string(a.patch_size) +
                    " points, the patch form " + std::to_string(patch_size));
  for (const auto& map : a.maps) {
    if (static_cast<int>(map.size()) != patch_size) throw SizeError(std::string(what) + ": a patch map has the wrong size");
    for (int r : map)
      if (r < 0 || r >= a.size) throw SizeError(std::string(what) + ": a patch map row is out of range");
  }
}

}  // namespace

// ---- VolumeForm

VolumeForm VolumeForm::assembled(std::shared_ptr<const VolumeForm> patch, std::shared_ptr<const PatchAssembly> assembly) {
  if (!patch || !assembly || patch->assembly_) throw ParameterError("VolumeForm::assembled: needs a patch form and an assembly");
  check_assembly(*assembly, patch->size(), "VolumeForm::assembled");
  VolumeForm f;
  f.triangular_ = patch->triangular_;
  f.n_ = patch->n_;
  f.m_ = patch->m_;
  f.patch_ = std::move(patch);
  f.assembly_ = std::move(assembly);
  return f;
}

int VolumeForm::size() const { return assembly_ ? assembly_->size : static_cast<int>(B_.cols()); }
int VolumeForm::nodes() const {
  return assembly_ ? patch_->nodes() * assembly_->patches() : static_cast<int>(w_.size());
}

double VolumeForm::assembled_value(const Eigen::MatrixX3d& P, bool scale) const {
  double v = 0.0;
  for (int p = 0; p < assembly_->patches(); ++p) {
    const Eigen::MatrixX3d Pp = patch_points(*assembly_, p, P);
    v += scale ? patch_->value_scale(Pp) : patch_->value(Pp);
  }
  return v;
}

Eigen::MatrixX3d VolumeForm::assembled_gradient(const Eigen::MatrixX3d& P, bool scale) const {
  Eigen::MatrixX3d G = Eigen::MatrixX3d::Zero(assembly_->size, 3);
  for (int p = 0; p < assembly_->patches(); ++p) {
    const Eigen::MatrixX3d Pp = patch_points(*assembly_, p, P);
    const Eigen::MatrixX3d Gp = scale ? patch_->gradient_scale(Pp) : patch_->gradient(Pp);
    const std::vector<int>& map = assembly_->maps[static_cast<std::size_t>(p)];
    for (std::size_t r = 0; r < map.size(); ++r) G.row(map[r]) += Gp.row(static_cast<Eigen::Index>(r));
  }
  return G;
}

Eigen::MatrixXd VolumeForm::assembled_hessian(const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                                              bool quadrature) const {
  return assembled_hessian_dense(*assembly_, P, idx, [&](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) {
    return quadrature ? patch_->hessian_quadrature(Pp, l) : patch_->hessian(Pp, l);
  });
}

void VolumeForm::assembled_rows_and_scale(const Eigen::MatrixX3d& P, const std::vector<int>& idx, Eigen::MatrixX3d* G,
                                          Eigen::MatrixX3d* S) const {
  if (G)
    *G = assembled_rows(*assembly_, P, idx, [&](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) {
      return patch_->gradient_rows(Pp, l);
    });
  if (S)
    *S = assembled_rows(*assembly_, P, idx, [&](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) {
      return patch_->gradient_scale_rows(Pp, l);
    });
}

// ---- AreaForm

AreaForm AreaForm::assembled(std::shared_ptr<const AreaForm> patch, std::shared_ptr<const PatchAssembly> assembly) {
  if (!patch || !assembly || patch->assembly_) throw ParameterError("AreaForm::assembled: needs a patch form and an assembly");
  check_assembly(*assembly, patch->size(), "AreaForm::assembled");
  AreaForm f;
  f.q_ = patch->q_;
  f.grading_ = patch->grading_;
  f.levels_ = patch->levels_;
  f.patch_ = std::move(patch);
  f.assembly_ = std::move(assembly);
  return f;
}

int AreaForm::size() const { return assembly_ ? assembly_->size : static_cast<int>(Bu_.cols()); }
int AreaForm::nodes() const { return assembly_ ? patch_->nodes() * assembly_->patches() : static_cast<int>(w_.size()); }

void AreaForm::assembled_rows_and_scale(const Eigen::MatrixX3d& P, const std::vector<int>& idx, Eigen::MatrixX3d* G,
                                        Eigen::MatrixX3d* S) const {
  // One pass per patch gives both: the patch's G and S of its local rows, added into idx's rows.
  const std::vector<int> where = positions(*assembly_, idx);
  const Eigen::Index k = static_cast<Eigen::Index>(idx.size());
  if (G) *G = Eigen::MatrixX3d::Zero(k, 3);
  if (S) *S = Eigen::MatrixX3d::Zero(k, 3);
  std::vector<int> local, pos;
  Eigen::MatrixX3d Gp, Sp;
  for (int p = 0; p < assembly_->patches(); ++p) {
    local_rows(*assembly_, p, where, local, pos);
    if (local.empty()) continue;
    patch_->gradient_rows_and_scale(patch_points(*assembly_, p, P), local, G ? &Gp : nullptr, S ? &Sp : nullptr);
    for (std::size_t r = 0; r < local.size(); ++r) {
      if (G) G->row(pos[r]) += Gp.row(static_cast<Eigen::Index>(r));
      if (S) S->row(pos[r]) += Sp.row(static_cast<Eigen::Index>(r));
    }
  }
}

}  // namespace bpde
