#include "app/inputs.h"

#include <utility>

#include "bezierpde/core/errors.h"
#include "bezierpde/jobs/run_job.h"

namespace bpde::app {

InputKind input_kind(const Json& j) {
  if (!j.is_object()) return InputKind::Unknown;
  if (j.contains("type")) return InputKind::Net;
  if (j.contains("net") && j.contains("report")) return InputKind::Result;
  if (j.contains("net") && j.contains("problem")) return InputKind::Job;
  if ((j.contains("kind") && j["kind"] == "blend") || j.contains("partition") || j.contains("epsilon") ||
      j.contains("edges") || j.contains("surfaces"))
    return InputKind::Blend;
  if (j.contains("net")) return InputKind::Job;
  return InputKind::Unknown;
}

namespace {

[[noreturn]] void wrong_command(const std::string& path, const char* what, const char* use) {
  throw ParseError(path + ": this is " + what + ": use `" + use + "`");
}

}  // namespace

AnyNet any_net_from_json(const Json& j, const std::string& path) {
  if (is_complex_net(j)) return complex_net_from_json(j, path);
  return net_from_json(j, path);
}

namespace {

// The net object of a net file or a result.json, and the path that names it; a job or a blend
// config is refused naming the command that takes it.
std::pair<const Json*, std::string> net_object(const Json& j, const std::string& path) {
  switch (input_kind(j)) {
    case InputKind::Result:
      return {&j["net"], path + ".net"};
    case InputKind::Job:
      wrong_command(path, "a job, not a net", "bpde solve");
    case InputKind::Blend:
      wrong_command(path, "a blend config, not a net", "bpde blend");
    case InputKind::Net:
    case InputKind::Unknown:
      break;
  }
  return {&j, path};
}

}  // namespace

AnyNet read_any_net_input(const std::string& path) {
  const Json j = read_json_file(path);
  const auto [net, where] = net_object(j, path);
  return any_net_from_json(*net, where);
}

Net read_net_input(const std::string& path) {
  const Json j = read_json_file(path);
  const auto [net, where] = net_object(j, path);
  if (is_complex_net(*net))
    throw UnsupportedProblem(where +
                             ": a patch complex; this subcommand takes a single net (`bpde sample`, `check`, "
                             "`view` and `export` take complexes)");
  return net_from_json(*net, where);
}

Job read_job_input(const std::string& path) {
  const Json j = read_json_file(path);
  switch (input_kind(j)) {
    case InputKind::Blend:
      wrong_command(path, "a blend config", "bpde blend");
    case InputKind::Net:
      wrong_command(path, "a net, not a job", "bpde sample` or `bpde check");
    case InputKind::Result:
      wrong_command(path, "a result.json, not a job", "bpde sample` or `bpde check");
    case InputKind::Job:
    case InputKind::Unknown:
      break;
  }
  return job_from_json(j, path);
}

BlendConfig read_blend_input(const std::string& path) {
  // The blend reader has its own messages for malformed text: only a file that parses is recognised.
  Json j;
  try {
    j = read_json_file(path);
  } catch (const InvalidInput&) {
    return read_blend_config(path);
  }
  switch (input_kind(j)) {
    case InputKind::Job:
      wrong_command(path, "a job", "bpde solve");
    case InputKind::Net:
      wrong_command(path, "a net, not a blend config", "bpde sample` or `bpde check");
    case InputKind::Result:
      wrong_command(path, "a result.json, not a blend config", "bpde sample` or `bpde check");
    case InputKind::Blend:
    case InputKind::Unknown:
      break;
  }
  return blend_config_from_json(j);
}

}  // namespace bpde::app
