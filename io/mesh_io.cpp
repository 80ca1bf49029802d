#include "bezierpde/io/mesh_io.h"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/sample_progress.h"
#include "bezierpde/io/vtp_io.h"

namespace bpde {
namespace {

struct File {
  std::FILE* f = nullptr;
  std::string path;
  explicit File(const std::string& p) : f(std::fopen(p.c_str(), "wb")), path(p) {
    if (!f) throw FileError("cannot write file '" + p + "'");
  }
  ~File() {
    if (f) std::fclose(f);
  }
  void close() {
    const bool bad = std::ferror(f) != 0;
    const int rc = std::fclose(f);
    f = nullptr;
    if (bad || rc != 0) throw FileError("error while writing '" + path + "'");
  }
};

// Lines are built in a buffer and written in blocks; numbers by std::to_chars: the shortest
// decimal that reads back to the same double (round trip exact, like %.17g, but without the
// rounding noise digits and several times faster than printf).
class LineBuffer {
 public:
  explicit LineBuffer(std::FILE* f) : f_(f) { buf_.reserve(kBlock + 256); }
  ~LineBuffer() { flush(); }
  LineBuffer& text(const char* s) {
    buf_ += s;
    return *this;
  }
  LineBuffer& text(std::string_view s) {
    buf_ += s;
    return *this;
  }
  LineBuffer& num(double x) {
    char tmp[32];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, x);
    buf_.append(tmp, r.ptr);
    return *this;
  }
  LineBuffer& num(long x) {
    char tmp[24];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, x);
    buf_.append(tmp, r.ptr);
    return *this;
  }
  LineBuffer& num(int x) { return num(static_cast<long>(x)); }
  LineBuffer& sp() {
    buf_ += ' ';
    return *this;
  }
  void end_line() {
    buf_ += '\n';
    if (buf_.size() >= kBlock) flush();
  }
  void flush() {
    if (!buf_.empty()) std::fwrite(buf_.data(), 1, buf_.size(), f_);
    buf_.clear();
  }

 private:
  static constexpr size_t kBlock = 1 << 16;
  std::FILE* f_;
  std::string buf_;
};

void write_vertices(LineBuffer& out, const Eigen::MatrixX3d& V, const SharedNumberText* text = nullptr) {
  for (Eigen::Index r = 0; r < V.rows(); ++r) {
    if (text)
      out.text("v ").text(text->vertex(r, 0)).sp().text(text->vertex(r, 1)).sp().text(text->vertex(r, 2));
    else
      out.text("v ").num(V(r, 0)).sp().num(V(r, 1)).sp().num(V(r, 2));
    out.end_line();
  }
}

// A SharedNumberText that is not of this mesh is a caller's bug.
const SharedNumberText* checked(const SharedNumberText* text, const TriangleMesh& mesh, const char* where) {
  if (text && text->vertices() != mesh.V.rows())
    throw InternalError(std::string(where) + ": the shared number text is not of this mesh");
  return text;
}

}  // namespace

SharedNumberText::SharedNumberText(const TriangleMesh& mesh, const SurfaceFields& fields) : vertices_(mesh.V.rows()) {
  if (fields.H.size() != vertices_) throw InternalError("SharedNumberText: fields do not match the mesh");
  const auto count = static_cast<std::size_t>(4 * vertices_);
  chars_.reserve(count * 20);
  begin_.reserve(count + 1);
  auto add = [&](double x) {
    char tmp[32];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, x);
    begin_.push_back(chars_.size());
    chars_.append(tmp, r.ptr);
  };
  for (Eigen::Index r = 0; r < vertices_; ++r)
    for (int c = 0; c < 3; ++c) add(mesh.V(r, c));
  for (Eigen::Index r = 0; r < vertices_; ++r) add(fields.H(r));
  begin_.push_back(chars_.size());
}

void write_obj(const std::string& path, const TriangleMesh& mesh, const SharedNumberText* text) {
  text = checked(text, mesh, "write_obj");
  File out(path);
  {
    LineBuffer b(out.f);
    b.text("# bezierpde surface: ").num(static_cast<long>(mesh.V.rows())).text(" vertices, ");
    b.num(static_cast<long>(mesh.F.rows())).text(" triangles");
    b.end_line();
    write_vertices(b, mesh.V, text);
    for (Eigen::Index r = 0; r < mesh.F.rows(); ++r) {
      b.text("f ").num(mesh.F(r, 0) + 1).sp().num(mesh.F(r, 1) + 1).sp().num(mesh.F(r, 2) + 1);
      b.end_line();
    }
  }
  out.close();
}

MeshFormat mesh_format_from_string(const std::string& s, const std::string& where) {
  if (s == "ascii") return MeshFormat::Ascii;
  if (s == "binary") return MeshFormat::Binary;
  throw ParseError(where + ": unknown mesh format \"" + s + "\" (expected ascii or binary)");
}

namespace {

// Little-endian bytes of a value appended to a buffer.
template <class T>
void put_le(std::vector<char>& buf, T value) {
  static_assert(std::endian::native == std::endian::little, "binary PLY writer assumes a little-endian host");
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  buf.insert(buf.end(), bytes, bytes + sizeof(T));
}

}  // namespace

void write_ply(const std::string& path, const TriangleMesh& mesh, const SurfaceFields& fields, MeshFormat format,
               const SharedNumberText* text) {
  text = checked(text, mesh, "write_ply");
  const bool binary = format == MeshFormat::Binary;
  const char* type = binary ? "float" : "double";
  File out(path);
  std::fprintf(out.f,
               "ply\nformat %s 1.0\ncomment bezierpde surface; mean_curvature per FORMATS.md sign convention; "
               "regular = 0 where x_u and x_v are parallel (mean_curvature there: the mean of the nearest regular vertices, ring by ring)\n"
               "element vertex %ld\nproperty %s x\nproperty %s y\nproperty %s z\nproperty %s mean_curvature\n"
               "property uchar regular\nelement face %ld\nproperty list uchar int vertex_indices\nend_header\n",
               binary ? "binary_little_endian" : "ascii", static_cast<long>(mesh.V.rows()), type, type, type, type,
               static_cast<long>(mesh.F.rows()));
  if (binary) {
    std::vector<char> buf;
    buf.reserve(static_cast<size_t>(mesh.V.rows()) * 17 + static_cast<size_t>(mesh.F.rows()) * 13);
    for (Eigen::Index r = 0; r < mesh.V.rows(); ++r) {
      for (int c = 0; c < 3; ++c) put_le(buf, static_cast<float>(mesh.V(r, c)));
      put_le(buf, static_cast<float>(fields.H(r)));
      put_le(buf, static_cast<std::uint8_t>(fields.regular(r)));
    }
    for (Eigen::Index r = 0; r < mesh.F.rows(); ++r) {
      put_le(buf, static_cast<std::uint8_t>(3));
      for (int c = 0; c < 3; ++c) put_le(buf, static_cast<std::int32_t>(mesh.F(r, c)));
    }
    std::fwrite(buf.data(), 1, buf.size(), out.f);
  } else {
    LineBuffer b(out.f);
    for (Eigen::Index r = 0; r < mesh.V.rows(); ++r) {
      if (text)
        b.text(text->vertex(r, 0)).sp().text(text->vertex(r, 1)).sp().text(text->vertex(r, 2)).sp();
      else
        b.num(mesh.V(r, 0)).sp().num(mesh.V(r, 1)).sp().num(mesh.V(r, 2)).sp();
      if (text)
        b.text(text->mean_curvature(r)).sp();
      else
        b.num(fields.H(r)).sp();
      b.num(static_cast<int>(fields.regular(r)));
      b.end_line();
    }
    for (Eigen::Index r = 0; r < mesh.F.rows(); ++r) {
      b.text("3 ").num(mesh.F(r, 0)).sp().num(mesh.F(r, 1)).sp().num(mesh.F(r, 2));
      b.end_line();
    }
  }
  out.close();
}

std::vector<std::array<int, 2>> net_segments(const Net& net) {
  std::vector<std::array<int, 2>> out;
  auto line = [&](int a, int b) { out.push_back({a, b}); };
  if (const auto* t = std::get_if<TensorNet>(&net)) {
    for (int i = 0; i <= t->n(); ++i)
      for (int j = 0; j <= t->m(); ++j) {
        if (i < t->n()) line(t->index(i, j), t->index(i + 1, j));
        if (j < t->m()) line(t->index(i, j), t->index(i, j + 1));
      }
  } else if (const auto* b = std::get_if<BSplineNet>(&net)) {
    for (int i = 0; i < b->nu(); ++i)
      for (int j = 0; j < b->nv(); ++j) {
        if (i + 1 < b->nu()) line(b->index(i, j), b->index(i + 1, j));
        if (j + 1 < b->nv()) line(b->index(i, j), b->index(i, j + 1));
      }
  } else {
    const auto& tr = std::get<TriangularNet>(net);
    const int n = tr.n();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n - i; ++j) {
        // neighbours of I = (i, j, k) towards I - e3 + e1, I - e3 + e2 and I - e1 + e2
        if (n - i - j > 0) {
          line(tr.index(i, j), tr.index(i + 1, j));
          line(tr.index(i, j), tr.index(i, j + 1));
        }
        if (i > 0) line(tr.index(i, j), tr.index(i - 1, j + 1));
      }
  }
  return out;
}

void write_net_obj(const std::string& path, const Net& net) {
  File out(path);
  {
    LineBuffer b(out.f);
    b.text("# bezierpde control net (").text(net_kind(net).c_str()).text(")");
    b.end_line();
    write_vertices(b, std::visit([](const auto& n) -> Eigen::MatrixX3d { return n.points(); }, net));
    for (const auto& [p, q] : net_segments(net)) {
      b.text("l ").num(p + 1).sp().num(q + 1);
      b.end_line();
    }
  }
  out.close();
}

TriangleMesh sample_net(const Net& net, int samples, const ProgressFn& progress) {
  return std::visit([&](const auto& n) { return sample_mesh(n, samples, progress); }, net);
}

void write_surface_files(const std::string& dir, const Net& net, const TriangleMesh& mesh, MeshFormat format) {
  const SurfaceFields fields = surface_fields(net, mesh);
  std::optional<SharedNumberText> text;  // in ASCII, coordinates and H formatted once for the three files
  if (format == MeshFormat::Ascii) text.emplace(mesh, fields);
  const SharedNumberText* shared = text ? &*text : nullptr;
  write_obj(dir + "/surface.obj", mesh, shared);
  write_ply(dir + "/surface.ply", mesh, fields, format, shared);
  write_vtp(dir + "/surface.vtp", mesh, fields, format, shared);
  write_net_obj(dir + "/net.obj", net);
}

}  // namespace bpde
