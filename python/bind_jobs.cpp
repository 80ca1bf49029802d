// The command contract (same JSON as `bpde`): solve, sample, energy, check, plate, blend.
#include "bindings.h"

#include <optional>

#include "bezierpde/io/blend_config.h"
#include "bezierpde/io/job.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_blend.h"
#include "bezierpde/jobs/run_energy.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/jobs/run_plate.h"

namespace bpde::python {

namespace {

// result.json's object for a job (the report completed with mean_curvature and check, as
// write_result completes it), written to `out` when given.
Json solve_result(const Json& job_json, const std::optional<std::string>& out) {
  const bpde::Job job = bpde::job_from_json(job_json, "job");
  const bpde::SolveOutcome outcome = bpde::run_job(job);
  if (out) return bpde::write_job_result(*out, job, outcome).result;
  return bpde::job_result_json(job, outcome);
}

void check_samples(int samples) {
  if (samples < 1 || samples > bpde::kMaxSamples)
    throw bpde::ParameterError("samples must be in 1.." + std::to_string(bpde::kMaxSamples) + ", got " +
                               std::to_string(samples));
}

}  // namespace

void bind_jobs(py::module_& m) {
  m.def(
      "solve_result",
      [](py::handle job, const std::optional<Text>& out_arg) {
        const std::optional<std::string> out = path_text(out_arg, "out");
        const Json j = to_json(job, "job");
        Json result;
        {
          py::gil_scoped_release release;
          InterruptibleJobs ctrl_c;
          result = solve_result(j, out);
        }
        return from_json(result);
      },
      py::arg("job"), py::arg("out") = py::none(),
      "result.json of `bpde solve` for a JOB dict (written to `out` with the surface files when given).");
  m.def(
      "sample",
      [](py::handle net, int samples, const std::optional<Text>& out_arg) {
        const std::optional<std::string> out = path_text(out_arg, "out");
        const bpde::Net n = net_arg(net);
        check_samples(samples);
        bpde::TriangleMesh mesh;
        {
          py::gil_scoped_release release;
          InterruptibleJobs ctrl_c;
          mesh = bpde::sample_net(n, samples);
          if (out) {
            bpde::write_output_files(*out, nullptr, n, mesh);  // as `bpde sample`: all or nothing
          }
        }
        return mesh_tuple(std::move(mesh));
      },
      py::arg("net"), py::arg("samples") = 50, py::arg("out") = py::none(),
      "(V, F, H) of `bpde sample`: vertices (V x 3 float64), triangles (F x 3 int32), mean curvature per vertex.");
  m.def(
      "energy",
      [](py::handle net, const Text& energy_arg, std::optional<double> H) {
        const bpde::Net n = net_arg(net);
        const std::string energy = text(energy_arg, "energy");
        Json r;
        {
          py::gil_scoped_release release;
          r = bpde::energy_report(n, energy, H, {"energy", "H"});
        }
        return from_json(r);
      },
      py::arg("net"), py::arg("energy"), py::arg("H") = py::none(), "What `bpde energy` prints, as a dict.");
  m.def(
      "check",
      [](py::handle net, int samples) {
        const bpde::Net n = net_arg(net);
        check_samples(samples);
        Json r;
        {
          py::gil_scoped_release release;
          InterruptibleJobs ctrl_c;
          r = bpde::check_report(bpde::sample_net(n, samples));
        }
        return from_json(r);
      },
      py::arg("net"), py::arg("samples") = 50, "What `bpde check` prints, as a dict (CGAL figures).");
  m.def(
      "check_mesh",
      [](py::handle V_arg, py::handle F_arg) {
        const Eigen::MatrixX3d V = points_arg<3>(V_arg, "V");
        require_finite(V, "V");
        const Eigen::MatrixX3i F = points_arg<3, int>(F_arg, "F");
        if (F.size() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= V.rows()))
          throw bpde::ParameterError("F: vertex indices must be in 0.." + std::to_string(V.rows() - 1));
        Json r;
        {
          py::gil_scoped_release release;
          r = bpde::check_report(bpde::TriangleMesh{V, F, Eigen::VectorXd(), {}});
        }
        return from_json(r);
      },
      py::arg("V"), py::arg("F"), "The CGAL figures of a mesh given as arrays.");
  m.def(
      "plate",
      [](double aspect, int degree, const Text& method_arg) {
        const std::string method = text(method_arg, "method");
        bpde::PlateOutcome out;
        {
          py::gil_scoped_release release;
          out = bpde::run_plate(aspect, degree, method, {"aspect", "method"});
        }
        return from_json(out.report);
      },
      py::arg("aspect"), py::arg("degree"), py::arg("method"), "What `bpde plate` prints, as a dict.");
  m.def(
      "blend_result",
      [](py::handle config, const std::optional<Text>& out_arg) {
        const std::optional<std::string> out = path_text(out_arg, "out");
        const bpde::BlendConfig c = bpde::blend_config_from_json(to_json(config, "config"));
        Json result;
        {
          py::gil_scoped_release release;
          InterruptibleJobs ctrl_c;
          const bpde::BlendOutcome o = bpde::run_blend(c);
          if (out) {
            bpde::write_blend_outcome(*out, c, o);
            result = bpde::read_json_file(*out + "/result.json");
          } else {
            const bpde::Net net(o.net);
            const Json report = bpde::complete_report(net, o.mesh, c.samples, o.report);
            result = {{"net", bpde::net_to_json(net)}, {"report", report}};
          }
        }
        return from_json(result);
      },
      py::arg("config"), py::arg("out") = py::none(), "result.json of `bpde blend` for a CONFIG dict.");
}

}  // namespace bpde::python
