// Sweeps: the one expansion (jobs/sweep.h), and one job run as the command runs it.
#include "bindings.h"

#include <vector>

#include "bezierpde/jobs/sweep.h"

namespace bpde::python {

void bind_sweep(py::module_& m) {
  m.def(
      "expand_sweep",
      [](py::handle spec, const Text& base_dir) {
        const bpde::SweepSpec s =
            bpde::sweep_from_json(to_json(spec, "spec"), "sweep", path_text(base_dir, "base_dir"));
        const std::vector<bpde::SweepJob> jobs = bpde::expand_sweep(s);
        py::list out;
        for (const bpde::SweepJob& j : jobs) {
          py::dict d;
          d["index"] = j.index;
          d["id"] = j.id;
          d["values"] = from_json(j.values);
          d["job"] = from_json(j.job);
          d["error"] = j.error;
          out.append(d);
        }
        py::list columns;
        for (const std::string& c : bpde::sweep_columns(s)) columns.append(c);
        return py::make_tuple(out, columns);
      },
      py::arg("spec"), py::arg("base_dir") = ".",
      "(jobs, columns): the sweep's jobs as dicts {index, id, values, job, error} and the table's columns.");
  m.def(
      "run_sweep_job",
      [](py::handle job, const Text& dir_arg, bool resume) {
        const std::string dir = path_text(dir_arg, "dir");
        bpde::SweepJob j;
        j.index = job["index"].cast<int>();
        j.id = job["id"].cast<std::string>();
        j.values = to_json(job["values"], "job[\"values\"]");
        j.job = to_json(job["job"], "job[\"job\"]");
        j.error = job["error"].cast<std::string>();
        Json row;
        {
          py::gil_scoped_release release;
          if (resume) row = bpde::finished_sweep_row(j, dir);
          if (row.is_null()) row = bpde::run_sweep_job(j, dir);
        }
        return from_json(row);
      },
      py::arg("job"), py::arg("dir"), py::arg("resume") = true,
      "Run one expanded job into `dir` as `bpde sweep` does; its row (a dict).");
  m.def(
      "write_sweep_tables",
      [](py::handle spec, const Text& base_dir, const Text& out_arg, py::handle rows) {
        const bpde::SweepSpec s =
            bpde::sweep_from_json(to_json(spec, "spec"), "sweep", path_text(base_dir, "base_dir"));
        const std::string out_dir = path_text(out_arg, "out_dir");
        std::vector<Json> r;
        for (auto row : rows) r.push_back(to_json(row, "rows"));
        py::gil_scoped_release release;
        bpde::write_sweep_tables(out_dir, s, r);
      },
      py::arg("spec"), py::arg("base_dir"), py::arg("out_dir"), py::arg("rows"),
      "Write out_dir/results.csv and results.jsonl as `bpde sweep` does.");
  m.def("sweep_boundary_names", &bpde::sweep_boundary_names);
  m.attr("MAX_SWEEP_THREADS") = bpde::kMaxSweepThreads;  // FORMATS.md "Input limits"
  m.def(
      "read_json_file",
      [](const Text& path) {
        const std::string p = path_text(path, "path");
        Json j;
        {
          py::gil_scoped_release release;
          j = bpde::read_json_file(p);
        }
        return from_json(j);
      },
      py::arg("path"),
      "A JSON file read as every bpde reader reads it (FORMATS.md \"Input limits\": size, nesting, a key "
      "given twice refused) -> dict.");
}

}  // namespace bpde::python
