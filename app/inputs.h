#pragma once
// The input files of the subcommands, recognised before they are parsed strictly (io/), so that a
// file given to the wrong subcommand gets one line naming the right one instead of the strict
// parser's first complaint (`unknown field "a"`, `missing field "type"`):
//   a net       {"type": ..., ...}                           bpde sample / check / energy
//   a result    {"net": NET, "report": {...}, ...}           (its net: bpde sample / check / energy)
//   a job       {"net": NET, "problem": {...}, ...}          bpde solve
//   a blend     {"kind": "blend", ...} or {"partition", ...} bpde blend
#include <string>

#include "bezierpde/io/blend_config.h"
#include "bezierpde/io/job.h"

namespace bpde::app {

enum class InputKind { Net, Result, Job, Blend, Unknown };

/// What a parsed JSON file looks like (by its top-level keys only; nothing is validated).
InputKind input_kind(const Json& j);

/// A net file, or the result.json bpde writes (its "net"). A job or blend config is a
/// ParseError naming the subcommand that takes it; otherwise the strict net reader decides.
Net read_net_input(const std::string& path);
/// A job file; a blend config, net or result is a ParseError naming the subcommand that takes it.
Job read_job_input(const std::string& path);
/// A blend config; a job, net or result is a ParseError naming the subcommand that takes it.
BlendConfig read_blend_input(const std::string& path);

}  // namespace bpde::app
