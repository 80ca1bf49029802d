// The sweep file reader (io/sweep_spec.h).
#include "bezierpde/io/sweep_spec.h"

#include <algorithm>

#include "bezierpde/core/errors.h"

namespace bpde {

namespace {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : path) {
    if (c == '.') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

bool all_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

// Set `path` in `j` to `v`; ParameterError naming `where` if a segment indexes something that is
// neither an object nor an array holding that index.
void set_path(Json& j, const std::string& path, const Json& v, const std::string& where) {
  Json* cur = &j;
  for (const std::string& s : split_path(path)) {
    Json* next = nullptr;
    if (cur->is_array() && all_digits(s)) {
      const size_t i = s.size() > 6 ? cur->size() : std::stoul(s);
      if (i >= cur->size())
        throw ParameterError(where + ": \"" + path + "\": index " + s + " out of range (the array has " +
                             std::to_string(cur->size()) + " elements)");
      next = &(*cur)[i];
    } else if (cur->is_object() || cur->is_null()) {
      next = &(*cur)[s];
    } else {
      throw ParameterError(where + ": \"" + path + "\": \"" + s + "\" indexes a " + cur->type_name());
    }
    cur = next;
  }
  *cur = v;
}

}  // namespace

const std::vector<std::string> kSweepResultColumns = {"status",        "exit_code",
                                                      "converged",     "energy",
                                                      "residual",      "H",
                                                      "H_min",         "H_max",
                                                      "H_mean",        "check_self_intersections",
                                                      "check_closed",  "check_volume",
                                                      "seconds",       "error",
                                                      "boundary_error"};

SweepSpec parse_sweep_spec(const Json& j, const std::string& source, const SweepBaseLoader& load_base,
                           const std::vector<std::string>& boundary_names) {
  json_read::require_object(j, source);
  json_read::check_keys(j, source, {"base", "axes", "boundary"});
  SweepSpec spec;
  const Json& base = json_read::field(j, source, "base");
  spec.base = base.is_string() ? load_base(base.get<std::string>()) : base;
  json_read::require_object(spec.base, source + ".base");
  if (j.contains("boundary")) {
    spec.boundary = json_read::string(j["boundary"], source + ".boundary");
    if (std::find(boundary_names.begin(), boundary_names.end(), spec.boundary) == boundary_names.end()) {
      std::string list;
      for (const std::string& n : boundary_names) {
        if (!list.empty()) list += ", ";
        list += n;
      }
      throw ParameterError(source + ".boundary: unknown boundary \"" + spec.boundary.substr(0, 80) +
                           "\" (known: " + list + ")");
    }
  }
  long total = 1;
  if (j.contains("axes")) {
    const Json& axes = j["axes"];
    json_read::require_object(axes, source + ".axes");
    for (auto it = axes.begin(); it != axes.end(); ++it) {
      const std::string where = source + ".axes." + it.key().substr(0, 80);
      const std::vector<std::string> seg = split_path(it.key());
      // As deep as the readers take (a deeper path writes a job.json that no reader accepts, and
      // its recursive conversions, to Python for one, would overflow the stack).
      if (seg.size() > static_cast<size_t>(kMaxJsonDepth))
        throw ParseError(source + ".axes: the path \"" + it.key().substr(0, 40) + "...\" has " +
                         std::to_string(seg.size()) + " segments, more than the limit of " +
                         std::to_string(kMaxJsonDepth));
      for (const std::string& s : seg)
        if (s.empty()) throw ParseError(where + ": an axis is a dotted path of non-empty keys");
      if (!it.value().is_array() || it.value().empty())
        throw ParseError(where + ": expected a non-empty array of values");
      // The row holds the axis values beside `index`, `job` and the result columns: an axis of
      // one of those names would overwrite its column and repeat the CSV header name.
      if (it.key() == "index" || it.key() == "job" ||
          std::find(kSweepResultColumns.begin(), kSweepResultColumns.end(), it.key()) != kSweepResultColumns.end())
        throw ParseError(where + ": \"" + it.key() + "\" is a column of the results table; name the axis by its path in the job");
      total *= static_cast<long>(it.value().size());
      if (total > kMaxSweepJobs)
        throw SizeError(source + ".axes: more than " + std::to_string(kMaxSweepJobs) + " jobs");
      SweepAxis axis;
      axis.path = it.key();
      for (const Json& v : it.value()) axis.values.push_back(v);
      spec.axes.push_back(std::move(axis));
    }
  }
  return spec;
}

std::size_t sweep_job_count(const SweepSpec& spec) {
  std::size_t total = 1;
  for (const SweepAxis& a : spec.axes) total *= a.values.size();
  return total;
}

void sweep_job_json(const SweepSpec& spec, std::size_t k, Json& job, Json& values, const std::string& where) {
  job = spec.base;
  values = Json::object();
  // Mixed radix, the last axis fastest.
  std::vector<size_t> digit(spec.axes.size());
  for (size_t a = spec.axes.size(); a-- > 0;) {
    digit[a] = k % spec.axes[a].values.size();
    k /= spec.axes[a].values.size();
  }
  for (size_t a = 0; a < spec.axes.size(); ++a) {
    const Json& v = spec.axes[a].values[digit[a]];
    values[spec.axes[a].path] = v;
    set_path(job, spec.axes[a].path, v, where);
  }
}

const Json* sweep_path_value(const Json& j, const std::string& path) {
  const Json* cur = &j;
  for (const std::string& s : split_path(path)) {
    if (cur->is_object() && cur->contains(s)) {
      cur = &(*cur)[s];
    } else if (cur->is_array() && all_digits(s) && s.size() <= 6 && std::stoul(s) < cur->size()) {
      cur = &(*cur)[std::stoul(s)];
    } else {
      return nullptr;
    }
  }
  return cur;
}

}  // namespace bpde
