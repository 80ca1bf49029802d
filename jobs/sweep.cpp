#include "bezierpde/jobs/sweep.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <thread>

#include <unistd.h>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/io/atomic_file.h"
#include "bezierpde/jobs/exit_status.h"
#include "bezierpde/jobs/run_job.h"

namespace bpde {

namespace fs = std::filesystem;

namespace {

// Create a folder of the sweep's own layout (DIR, DIR/jobs, DIR/jobs/<id>) with its parents; a
// job's files go into its folder all or nothing (write_job_result, io/output_folder.h).
void make_output_dir(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw FileError("cannot create the folder '" + dir + "'");
}

// Before any job runs: --out, when it exists, is a folder this process can write, and each table
// (results.csv, results.jsonl) is absent or a file the final rename can replace. A sweep that
// could not write its tables fails here, with nothing run and nothing left in --out.
void check_sweep_outputs(const std::string& out_dir) {
  std::error_code ec;
  const fs::file_status st = fs::status(out_dir, ec);
  if (!fs::exists(st)) return;  // created by make_output_dir, which reports a failure
  if (!fs::is_directory(st)) throw FileError("--out '" + out_dir + "' is not a folder");
  if (::access(out_dir.c_str(), W_OK | X_OK) != 0) throw FileError("cannot write into the folder '" + out_dir + "'");
  for (const char* name : {"results.csv", "results.jsonl"}) {
    const std::string path = out_dir + "/" + name;
    const fs::file_status t = fs::symlink_status(path, ec);
    if (fs::exists(t) && !fs::is_regular_file(t) && !fs::is_symlink(t))
      throw FileError("'" + path + "' exists and is not a file: the sweep cannot replace it");
  }
}

int builder_degree(const Json& degree, bool tensor) {
  const std::string where = "net.degree";
  int n = 0;
  if (tensor && degree.is_array()) {
    const std::vector<double> d = json_read::numbers(degree, where, 2);
    if (d[0] != d[1])
      throw DegreeError(where + ": the sphere-square boundary is built with n = m, got [" + std::to_string(d[0]) +
                        ", " + std::to_string(d[1]) + "]");
    n = json_read::integer(degree[0], where + "[0]");
  } else {
    n = json_read::integer(degree, where);
  }
  if (n < 1 || n > 64)
    throw DegreeError(where + ": a reference boundary is built at degree 1..64, got " + std::to_string(n));
  return n;
}

struct BuilderRegistry {
  std::mutex mutex;
  std::map<std::string, SweepBoundaryBuilder> builders;
  BuilderRegistry() {
    builders["circle-three-arcs"] = [](const Json& d) {
      return net_to_json(circle_three_arcs(builder_degree(d, false)));
    };
    builders["sphere-triangle"] = [](const Json& d) {
      return net_to_json(triangular_boundary(builder_degree(d, false), sphere_triangle));
    };
    builders["sphere-square"] = [](const Json& d) {
      return net_to_json(tensor_boundary(builder_degree(d, true), sphere_square));
    };
  }
};

BuilderRegistry& registry() {
  static BuilderRegistry r;
  return r;
}

std::string job_id(int index, size_t total) {
  int width = 4;
  for (size_t t = 10000; t < total; t *= 10) ++width;
  char buf[32];
  std::snprintf(buf, sizeof buf, "job-%0*d", width, index);
  return buf;
}

Json field_or_null(const Json& j, const char* key) { return j.is_object() && j.contains(key) ? j[key] : Json(nullptr); }

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Json base_row(const SweepJob& job) {
  Json row = Json::object();
  row["index"] = job.index;
  row["job"] = job.id;
  for (auto it = job.values.begin(); it != job.values.end(); ++it) row[it.key()] = it.value();
  for (const std::string& c : kSweepResultColumns) row[c] = nullptr;
  return row;
}

void write_text_atomically(const std::string& path, const std::string& text) { write_file_atomically(path, text); }

std::string csv_cell(const Json& v) {
  if (v.is_null()) return "";
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number_unsigned()) return std::to_string(v.get<unsigned long long>());
  if (v.is_number_float()) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v.get<double>());
    return buf;
  }
  const std::string s = v.is_string() ? v.get<std::string>() : v.dump();
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

}  // namespace

SweepSpec sweep_from_json(const Json& j, const std::string& source, const std::string& base_dir) {
  return parse_sweep_spec(
      j, source, [&](const std::string& name) { return read_json_file((fs::path(base_dir) / name).string()); },
      sweep_boundary_names());
}

SweepSpec read_sweep_file(const std::string& path) {
  const Json j = read_json_file(path);
  const fs::path dir = fs::path(path).parent_path();
  return sweep_from_json(j, path, dir.empty() ? "." : dir.string());
}

std::vector<SweepJob> expand_sweep(const SweepSpec& spec) {
  const size_t total = sweep_job_count(spec);
  std::vector<SweepJob> jobs(total);
  for (size_t k = 0; k < total; ++k) {
    SweepJob& job = jobs[k];
    job.index = static_cast<int>(k);
    job.id = job_id(job.index, total);
    try {
      sweep_job_json(spec, k, job.job, job.values, job.id);
      if (!spec.boundary.empty()) {
        const Json* degree = sweep_path_value(job.job, "net.degree");
        if (!degree) throw ParseError(job.id + ": net.degree: required by the boundary \"" + spec.boundary + "\"");
        job.job["net"] = build_sweep_boundary(spec.boundary, *degree);
      }
    } catch (const InvalidInput& e) {
      job.error = e.what();
    }
  }
  return jobs;
}

void register_sweep_boundary(const std::string& name, SweepBoundaryBuilder builder) {
  std::lock_guard<std::mutex> lock(registry().mutex);
  registry().builders[name] = std::move(builder);
}

std::vector<std::string> sweep_boundary_names() {
  std::lock_guard<std::mutex> lock(registry().mutex);
  std::vector<std::string> names;
  for (const auto& [name, b] : registry().builders) names.push_back(name);
  return names;
}

Json build_sweep_boundary(const std::string& name, const Json& degree) {
  SweepBoundaryBuilder b;
  {
    std::lock_guard<std::mutex> lock(registry().mutex);
    auto it = registry().builders.find(name);
    if (it == registry().builders.end()) throw ParameterError("boundary: unknown boundary \"" + name + "\"");
    b = it->second;
  }
  return b(degree);
}

std::vector<std::string> sweep_columns(const SweepSpec& spec) {
  std::vector<std::string> c = {"index", "job"};
  for (const SweepAxis& a : spec.axes) c.push_back(a.path);
  c.insert(c.end(), kSweepResultColumns.begin(), kSweepResultColumns.end());
  return c;
}

Json run_sweep_job(const SweepJob& job, const std::string& dir) {
  const double t0 = now_seconds();
  Json row = base_row(job);
  try {
    make_output_dir(dir);
    for (const char* f : {"row.json", "result.json", "surface.obj", "surface.ply", "surface.vtp", "net.obj"}) {
      std::error_code ec;
      fs::remove(fs::path(dir) / f, ec);
    }
    write_json_file(dir + "/job.json", job.job);
    if (!job.error.empty()) throw ParameterError(job.error);
    const Job parsed = job_from_json(job.job, job.id);
    const SolveOutcome out = run_job(parsed);
    const WrittenResult written = write_job_result(dir, parsed, out);
    const Json& rep = written.result["report"];
    row["status"] = to_string(out.status);
    row["exit_code"] = written.exit_code;
    row["converged"] = out.converged;
    row["energy"] = field_or_null(rep, "energy");
    row["residual"] = rep.contains("residual") ? rep["residual"] : field_or_null(rep, "pde_residual");
    row["H"] = field_or_null(rep, "H");
    const Json mc = field_or_null(rep, "mean_curvature");
    row["H_min"] = field_or_null(mc, "min");
    row["H_max"] = field_or_null(mc, "max");
    row["H_mean"] = field_or_null(mc, "mean");
    const Json ck = field_or_null(rep, "check");
    row["check_self_intersections"] = field_or_null(ck, "self_intersections");
    row["check_closed"] = field_or_null(ck, "closed");
    row["check_volume"] = field_or_null(ck, "volume");
    if (!out.converged) row["error"] = field_or_null(rep, "message");
    // Boundary-form jobs: the largest fitting error of the edges (a degree axis shows the
    // boundary converging with the surface).
    if (rep.contains("boundary_fit") && rep["boundary_fit"].is_array()) {
      double worst = 0;
      for (const Json& e : rep["boundary_fit"])
        if (e.contains("max_error") && e["max_error"].is_number())
          worst = std::max(worst, e["max_error"].get<double>());
      row["boundary_error"] = worst;
    }
  } catch (...) {
    const ErrorExit e = error_exit(std::current_exception());
    row["status"] = e.code == 2 ? "invalid-input" : "internal-error";
    row["exit_code"] = e.code;
    row["converged"] = false;
    std::string line = e.line;
    while (!line.empty() && line.back() == '\n') line.pop_back();
    row["error"] = line;
  }
  row["seconds"] = now_seconds() - t0;
  try {
    write_text_atomically(dir + "/row.json", row.dump() + "\n");
  } catch (...) {
    // The row is still returned: a folder that cannot take row.json only loses the resume.
  }
  return row;
}

Json finished_sweep_row(const SweepJob& job, const std::string& dir) {
  try {
    if (!fs::exists(dir + "/row.json") || !fs::exists(dir + "/job.json")) return nullptr;
    if (read_json_file(dir + "/job.json") != job.job) return nullptr;
    Json row = read_json_file(dir + "/row.json");
    if (!row.is_object() || !row.contains("exit_code") || !row["exit_code"].is_number_integer()) return nullptr;
    const int code = row["exit_code"].get<int>();
    if (code < 0 || code > 2) return nullptr;
    if (row.value("job", std::string()) != job.id) return nullptr;
    // A row written before a column was added is run again, so that every row has every column.
    for (const std::string& c : kSweepResultColumns)
      if (!row.contains(c)) return nullptr;
    return row;
  } catch (...) {
    return nullptr;
  }
}

std::vector<Json> run_sweep(const SweepSpec& spec, const std::string& out_dir, const SweepRunOptions& options) {
  if (options.jobs < 0 || options.jobs > kMaxSweepThreads)
    throw ParameterError("jobs: expected 0.." + std::to_string(kMaxSweepThreads) + ", got " +
                         std::to_string(options.jobs));
  const std::vector<SweepJob> jobs = expand_sweep(spec);
  check_sweep_outputs(out_dir);
  make_output_dir(out_dir + "/jobs");
  const double t0 = now_seconds();
  std::vector<Json> rows(jobs.size());
  std::vector<size_t> todo;
  int resumed = 0;
  for (size_t k = 0; k < jobs.size(); ++k) {
    Json row = options.resume ? finished_sweep_row(jobs[k], out_dir + "/jobs/" + jobs[k].id) : Json(nullptr);
    if (row.is_null()) {
      todo.push_back(k);
    } else {
      rows[k] = std::move(row);
      ++resumed;
    }
  }
  std::mutex mutex;
  SweepProgress progress;
  progress.total = static_cast<int>(jobs.size());
  progress.done = resumed;
  progress.resumed = resumed;
  if (options.on_progress) options.on_progress(progress);

  // An exception that escapes a job's row (out of memory while building it, a progress callback
  // that throws) stops the other workers at their next job and is rethrown here once every thread
  // is joined: never std::terminate from a worker thread.
  std::atomic<size_t> next{0};
  std::exception_ptr failure;
  auto worker = [&]() noexcept {
    try {
      for (;;) {
        const size_t t = next.fetch_add(1);
        if (t >= todo.size()) return;
        const size_t k = todo[t];
        Json row = run_sweep_job(jobs[k], out_dir + "/jobs/" + jobs[k].id);
        std::lock_guard<std::mutex> lock(mutex);
        rows[k] = std::move(row);
        ++progress.done;
        progress.seconds = now_seconds() - t0;
        progress.row = &rows[k];
        if (options.on_progress) options.on_progress(progress);
        progress.row = nullptr;
      }
    } catch (...) {
      next.store(todo.size());
      std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  unsigned n =
      options.jobs > 0 ? static_cast<unsigned>(options.jobs) : std::max(1u, std::thread::hardware_concurrency());
  n = std::min<unsigned>(n, static_cast<unsigned>(std::max<size_t>(1, todo.size())));
  std::vector<std::thread> pool;
  try {
    pool.reserve(n);
    for (unsigned i = 1; i < n; ++i) pool.emplace_back(worker);
  } catch (const std::exception&) {
    // The system refused another thread (std::system_error: EAGAIN, out of memory for its
    // stack) or the pool's memory: run with the threads already started.
  }
  worker();
  for (std::thread& th : pool) th.join();
  if (failure) std::rethrow_exception(failure);
  write_sweep_tables(out_dir, spec, rows);
  return rows;
}

std::string sweep_csv(const SweepSpec& spec, const std::vector<Json>& rows) {
  const std::vector<std::string> cols = sweep_columns(spec);
  std::string out;
  for (size_t c = 0; c < cols.size(); ++c) {
    if (c) out += ',';
    out += csv_cell(Json(cols[c]));
  }
  out += "\n";
  for (const Json& row : rows) {
    for (size_t c = 0; c < cols.size(); ++c) {
      if (c) out += ',';
      out += csv_cell(field_or_null(row, cols[c].c_str()));
    }
    out += "\n";
  }
  return out;
}

void write_sweep_tables(const std::string& out_dir, const SweepSpec& spec, const std::vector<Json>& rows) {
  make_output_dir(out_dir);
  write_text_atomically(out_dir + "/results.csv", sweep_csv(spec, rows));
  std::string jsonl;
  for (const Json& row : rows) jsonl += row.dump() + "\n";
  write_text_atomically(out_dir + "/results.jsonl", jsonl);
}

}  // namespace bpde
