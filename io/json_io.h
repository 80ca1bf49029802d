#pragma once
// JSON files of FORMATS.md: reading (strict) and writing of nets. The io/ folder is the only
// place of the library that knows the file formats.
//
// Strictness: malformed JSON, duplicate keys, unknown fields, values of the wrong JSON type,
// numbers that overflow (1e999), non-finite values, degrees out of 1..64 (checked before the
// point count) and wrong point counts all throw InvalidInput subclasses whose message names the
// JSON path, e.g. `net.points[3][1]: expected a number`.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "bezierpde/tensor/bspline_net.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

using Json = nlohmann::json;
/// Any net of FORMATS.md.
using Net = std::variant<TensorNet, TriangularNet, BSplineNet>;

/// Input limits of every JSON reader (docs/FORMATS.md "Limits"): a file or text of more than
/// kMaxJsonBytes bytes is refused (FileError), and arrays/objects nested more than kMaxJsonDepth
/// levels deep (ParseError). Both are bad input (exit 2).
inline constexpr std::size_t kMaxJsonBytes = std::size_t{64} << 20;  // 64 MiB
inline constexpr int kMaxJsonDepth = 256;
/// Largest magnitude of an integer field (degrees, samples, partition): json_read::integer
/// refuses larger ones (ParseError naming the number as written, 18446744073709551615 included).
inline constexpr std::int64_t kMaxJsonInteger = 1000000000;

/// Parse JSON text; `source` names it in errors (a file name). Throws ParseError (malformed,
/// too deep, a duplicate key), NumberOverflowError (a number beyond double range, such as 1e999:
/// both a ParseError and a NonFiniteError), or FileError when the text exceeds kMaxJsonBytes.
/// Every reader of io/ (nets, jobs, blend configs, `--energy`) parses through this function.
Json parse_json(const std::string& text, const std::string& source);
/// Read and parse a file (at most kMaxJsonBytes + 1 bytes are read, so endless input such as
/// /dev/zero stops there). Throws FileError (missing, unreadable, too large) or ParseError.
Json read_json_file(const std::string& path);
/// Write `j` to a file (pretty-printed, full double precision). Throws FileError.
void write_json_file(const std::string& path, const Json& j);
/// The bytes write_json_file writes: `j` indented by 2, and a final newline.
std::string json_file_text(const Json& j);

/// Strict readers used by every parser of io/ (path is the JSON path for messages).
namespace json_read {
void require_object(const Json& j, const std::string& path);
/// Throws ParseError naming the first key of `j` not in `allowed`.
void check_keys(const Json& j, const std::string& path, std::initializer_list<const char*> allowed);
const Json& field(const Json& j, const std::string& path, const char* key);  // required
double number(const Json& j, const std::string& path);                       // finite number
int integer(const Json& j, const std::string& path);                         // |integer| <= kMaxJsonInteger
std::string string(const Json& j, const std::string& path);
bool boolean(const Json& j, const std::string& path);
/// An array of `len` numbers (len < 0: any length).
std::vector<double> numbers(const Json& j, const std::string& path, int len = -1);
/// An array of [x, y, z] triples as a #points by 3 matrix.
Eigen::MatrixX3d points(const Json& j, const std::string& path);
}  // namespace json_read

/// Net from its JSON object (FORMATS.md "Nets"); `path` prefixes error messages.
Net net_from_json(const Json& j, const std::string& path = "net");
/// Read a net file.
Net read_net_file(const std::string& path);

Json net_to_json(const TensorNet& net);
Json net_to_json(const TriangularNet& net);
Json net_to_json(const BSplineNet& net);
Json net_to_json(const Net& net);

/// "tensor", "triangular" or "bspline".
std::string net_kind(const Net& net);

}  // namespace bpde
