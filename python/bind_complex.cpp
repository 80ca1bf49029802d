// Patch complexes (complex/patch_complex.h, FORMATS.md "Patch complexes"): built from loops as a
// job's "boundary" builds them, solved by the extremal and the cmc solvers, sampled into one mesh.
#include "bindings.h"

#include <string>
#include <vector>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/io/complex_job.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/cmc/complex_cmc.h"
#include "bezierpde/solvers/complex/complex_extremal.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde::python {

namespace {

// The limits of FORMATS.md "Input limits" for a complex, as a complex job checks them when it is
// read: its invariants (patch count, rows), the degree and the Gram entries.
void check_complex(const bpde::PatchComplex& c, const std::string& where) {
  bpde::validate(c);
  const int n = c.patches.front().degree;
  if (n > bpde::kMaxComplexExtremalDegree)
    throw bpde::DegreeError(where + ": a complex takes degrees up to " + std::to_string(bpde::kMaxComplexExtremalDegree) +
                            " (its Bernstein Gram systems lose a digit per degree), got " + std::to_string(n));
  if (bpde::complex_gram_entries(c) > bpde::kMaxComplexGramEntries)
    throw bpde::SizeError(where + ": the complex has more than " + std::to_string(bpde::kMaxComplexGramEntries) +
                          " Gram entries (patches x (control points per patch)^2)");
}

bpde::FitMethod fit_arg(const std::string& s) {
  if (s == "interpolation") return bpde::FitMethod::Interpolation;
  if (s == "least-squares") return bpde::FitMethod::LeastSquares;
  if (s == "geometric") return bpde::FitMethod::Geometric;
  throw bpde::ParameterError("fit: expected \"interpolation\", \"least-squares\" or \"geometric\", got \"" + s + "\"");
}

py::object patch_net(const bpde::PatchComplex& c, int p) {
  if (p < 0 || p >= static_cast<int>(c.patches.size()))
    throw bpde::SizeError("patch: expected 0.." + std::to_string(c.patches.size() - 1) + ", got " + std::to_string(p));
  if (c.patches[static_cast<size_t>(p)].kind == bpde::PatchKind::triangular) return py::cast(bpde::triangular_net(c, p));
  return py::cast(bpde::tensor_net(c, p));
}

}  // namespace

void bind_complex(py::module_& m) {
  py::class_<bpde::PatchComplex>(
      m, "PatchComplex",
      "Patches of one kind and degree sharing control points along their common edges "
      "(complex/patch_complex.h): `points` (N x 3), each patch's rows into them, the `fixed` rows.")
      .def_property_readonly("kind",
                             [](const bpde::PatchComplex& c) {
                               if (c.patches.empty()) return std::string("empty");
                               return std::string(c.patches.front().kind == bpde::PatchKind::triangular ? "triangular"
                                                                                                        : "tensor");
                             })
      .def_property_readonly("degree",
                             [](const bpde::PatchComplex& c) { return c.patches.empty() ? 0 : c.patches.front().degree; })
      .def("__len__", [](const bpde::PatchComplex& c) { return c.patches.size(); }, "The number of patches.")
      .def_property(
          "points", [](const bpde::PatchComplex& c) { return adopt(Eigen::MatrixX3d(c.points)); },
          [](bpde::PatchComplex& c, py::handle points) {
            const Eigen::MatrixX3d P = points_arg<3>(points, "points", c.points.rows());
            require_finite(P, "points");
            c.points = P;
          },
          "The control points of the complex (a copy, N x 3); set a new N x 3 array to change them.")
      .def_property_readonly("fixed", [](const bpde::PatchComplex& c) { return c.fixed; },
                             "The rows held by the boundary data (sorted).")
      .def(
          "patch_rows",
          [](const bpde::PatchComplex& c, int p) {
            if (p < 0 || p >= static_cast<int>(c.patches.size()))
              throw bpde::SizeError("patch: expected 0.." + std::to_string(c.patches.size() - 1) + ", got " +
                                    std::to_string(p));
            return c.patches[static_cast<size_t>(p)].points;
          },
          py::arg("patch"), "The rows of `points` that patch p uses, in its net's local order.")
      .def("patch", &patch_net, py::arg("patch"),
           "Patch p as a TriangularNet or TensorNet (its control points gathered in local order).")
      .def_property_readonly(
          "patches",
          [](const bpde::PatchComplex& c) {
            py::list out;
            for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) out.append(patch_net(c, p));
            return out;
          },
          "Every patch as a net, in order.")
      .def("__repr__", [](const bpde::PatchComplex& c) {
        return "<PatchComplex " + std::to_string(c.patches.size()) + " patches, " + std::to_string(c.points.rows()) +
               " points>";
      });

  m.def(
      "complex_from_boundary",
      [](py::handle boundary, const Text& fit_arg_text) {
        const bpde::FitMethod fit = fit_arg(text(fit_arg_text, "fit"));
        const Json j = to_json(boundary, "boundary");
        bpde::ComplexJobData data;
        {
          py::gil_scoped_release release;
          data = bpde::complex_from_json(j, "boundary", fit);
        }
        // The C¹ solve needs the complex's planar domain and its seam conditions, which the
        // entry points below do not take: such a job runs through bezierpde.solve.
        if (data.continuity != bpde::Continuity::C0)
          throw bpde::UnsupportedProblem(
              "boundary.continuity: the complex entry points solve C0 complexes; run a \"C1\" complex as a job "
              "(bezierpde.solve)");
        return data.complex;
      },
      py::arg("boundary"), py::arg("fit") = "interpolation",
      "The patch complex of a job's \"boundary\" dict of \"type\": \"complex\" (FORMATS.md \"Patch "
      "complexes\": loops, degree, refine, ...), its boundary rows fitted and fixed (the other rows hold the "
      "layout's start values, which every solve replaces). "
      "`fit` is the default fit of the curves (a job's default: \"interpolation\", \"geometric\" for the "
      "area and mean-curvature functionals). Bad input raises the job's errors; \"continuity\": \"C1\" "
      "raises UnsupportedProblem (run such a complex as a job with bezierpde.solve).");

  py::class_<bpde::ComplexExtremal>(m, "ComplexExtremalResult", "A complex extremal: complex, energy, summary.")
      .def_readonly("complex", &bpde::ComplexExtremal::complex)
      .def_readonly("energy", &bpde::ComplexExtremal::energy)
      .def_readonly("summary", &bpde::ComplexExtremal::summary);
  m.def(
      "solve_complex_extremal",
      [](const bpde::PatchComplex& data, py::handle energy) {
        const bpde::EnergySpec spec = energy_arg(energy);
        check_complex(data, "solve_complex_extremal");
        py::gil_scoped_release release;
        InterruptibleSolve ctrl_c;
        return bpde::solve_complex_extremal(data, spec);
      },
      py::arg("data"), py::arg("energy"),
      "The minimiser of a quadratic energy (a name or an ENERGY dict) over the free rows of the complex, "
      "its fixed rows held (a complex job's \"extremal\") -> ComplexExtremalResult.");

  // CmcResult<PatchComplex>: the fields of CmcResultTriangular/CmcResultTensor that a complex has.
  using R = bpde::CmcResult<bpde::PatchComplex>;
  py::class_<R>(m, "CmcResultComplex")
      .def_readonly("net", &R::net, "The complex with the solved points.")
      .def_readonly("H", &R::H)
      .def_readonly("D", &R::D)
      .def_readonly("V", &R::V)
      .def_readonly("DH", &R::DH)
      .def_readonly("A", &R::A)
      .def_readonly("energy", &R::energy)
      .def_property_readonly("functional", [](const R& r) { return bpde::to_string(r.functional); })
      .def_readonly("continuation_steps", &R::continuation_steps)
      .def_readonly("summary", &R::summary);
  m.def(
      "solve_cmc",
      [](const bpde::PatchComplex& data, const bpde::CmcOptions& options) {
        check_complex(data, "solve_cmc");
        bpde::CmcOptions o = options;
        o.progress = interruptible(options.progress);
        py::gil_scoped_release release;
        InterruptibleSolve ctrl_c;
        return bpde::solve_cmc(data, o);
      },
      py::arg("data"), py::arg("options"),
      "The cmc problem on a PatchComplex (solvers/cmc/complex_cmc.h; fixed \"boundary\") -> CmcResultComplex "
      "(net: the solved complex).");

  m.def(
      "sample_complex",
      [](const bpde::PatchComplex& c, int samples) {
        if (samples < 1 || samples > bpde::kMaxSamples)
          throw bpde::ParameterError("samples must be in 1.." + std::to_string(bpde::kMaxSamples) + ", got " +
                                     std::to_string(samples));
        bpde::validate(c);
        require_finite(c.points, "points");
        bpde::ComplexMesh mesh;
        {
          py::gil_scoped_release release;
          mesh = bpde::sample_complex(c, samples);
        }
        Eigen::VectorXi patch = std::move(mesh.patch);
        py::tuple vfh = mesh_tuple(std::move(mesh.mesh));
        return py::make_tuple(vfh[0], vfh[1], vfh[2], adopt(std::move(patch)));
      },
      py::arg("complex"), py::arg("samples") = 50,
      "(V, F, H, patch) of the complex's welded mesh (as `bpde solve` writes it): vertices (V x 3), "
      "triangles (F x 3), mean curvature per vertex, and the patch of each triangle.");
}

}  // namespace bpde::python
