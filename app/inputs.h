#pragma once
// The input files of the subcommands, recognised before they are parsed strictly (io/), so that a
// file given to the wrong subcommand gets one line naming the right one instead of the strict
// parser's first complaint (`unknown field "a"`, `missing field "type"`):
//   a net       {"type": ..., ...}                           bpde sample / check / energy / export
//               ({"type": "complex", ...}, a patch complex:   bpde sample / check / export; view)
//   a result    {"net": NET, "report": {...}, ...}           (its net: bpde sample / check / energy)
//   a job       {"net": NET, "problem": {...}, ...}          bpde solve
//   a blend     {"kind": "blend", ...} or {"partition", ...} bpde blend
#include <string>
#include <variant>

#include "bezierpde/io/blend_config.h"
#include "bezierpde/io/complex_json.h"
#include "bezierpde/io/job.h"

namespace bpde::app {

enum class InputKind { Net, Result, Job, Blend, Unknown };

/// What a parsed JSON file looks like (by its top-level keys only; nothing is validated).
InputKind input_kind(const Json& j);

/// A net file, or the result.json bpde writes (its "net"). A job or blend config is a
/// ParseError naming the subcommand that takes it, a patch complex an UnsupportedProblem (the
/// subcommand takes a single net); otherwise the strict net reader decides.
Net read_net_input(const std::string& path);
/// A net or a patch complex (io/complex_json.h).
using AnyNet = std::variant<Net, ComplexNetFile>;
/// A net file or complex net file, or the result.json bpde writes (its "net", a single net or a
/// complex). A job or blend config is a ParseError naming the subcommand that takes it.
AnyNet read_any_net_input(const std::string& path);
/// The "net" of a parsed result.json (`path` names it): a net or a complex.
AnyNet any_net_from_json(const Json& j, const std::string& path);

/// A job file; a blend config, net or result is a ParseError naming the subcommand that takes it.
Job read_job_input(const std::string& path);
/// A blend config; a job, net or result is a ParseError naming the subcommand that takes it.
BlendConfig read_blend_input(const std::string& path);

}  // namespace bpde::app
