#include "bezierpde/io/vtp_io.h"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/atomic_file.h"
#include "bezierpde/io/base64.h"

namespace bpde {
namespace {

static_assert(std::endian::native == std::endian::little, "the VTP writer declares LittleEndian");

// One DataArray: `values` row-major (#rows x components), written as Float64/Float32 text or
// base64, or Int32/UInt8 for integer types.
class ArrayWriter {
 public:
  ArrayWriter(std::string& out, bool binary) : out_(out), binary_(binary) {}

  void reals(const char* name, const double* values, size_t count, int components) {
    open(binary_ ? "Float32" : "Float64", name, components);
    if (binary_) {
      std::vector<float> f(values, values + count);
      payload(f.data(), f.size() * sizeof(float));
    } else {
      for (size_t k = 0; k < count; ++k) {
        const std::string_view t = text_of(values[k]);
        out_.append(t.data(), t.size());
        separator(k, components);
      }
    }
    close();
  }

  // The same text as reals() of the values that `text(k)` formats (SharedNumberText).
  template <class Text>
  void texts(const char* name, size_t count, int components, Text text) {
    open("Float64", name, components);
    for (size_t k = 0; k < count; ++k) {
      out_ += text(k);
      separator(k, components);
    }
    close();
  }

  template <class Int>
  void ints(const char* type, const char* name, const std::vector<Int>& values, int components) {
    open(type, name, components);
    if (binary_) {
      payload(values.data(), values.size() * sizeof(Int));
    } else {
      for (size_t k = 0; k < values.size(); ++k) number(static_cast<long long>(values[k]), k, components);
    }
    close();
  }

 private:
  void open(const char* type, const char* name, int components) {
    out_ += "        <DataArray type=\"";
    out_ += type;
    out_ += "\"";
    if (name) {
      out_ += " Name=\"";
      out_ += name;
      out_ += "\"";
    }
    out_ += " NumberOfComponents=\"" + std::to_string(components) + "\" format=\"";
    out_ += binary_ ? "binary" : "ascii";
    out_ += "\">\n";
  }
  void close() { out_ += "\n        </DataArray>\n"; }
  template <class T>
  void number(T value, size_t k, int components) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, value);
    out_.append(buf, r.ptr);
    separator(k, components);
  }
  void separator(size_t k, int components) { out_ += (k + 1) % (static_cast<size_t>(components) * 4) == 0 ? '\n' : ' '; }
  void payload(const void* data, size_t bytes) {
    std::vector<char> block(sizeof(std::uint64_t) + bytes);
    const std::uint64_t n = bytes;
    std::memcpy(block.data(), &n, sizeof n);
    if (bytes) std::memcpy(block.data() + sizeof n, data, bytes);
    out_ += base64_encode(block.data(), block.size());
  }

  // The shortest round-trip text of x (std::to_chars), through a direct-mapped cache of the last
  // value per slot: the uv parameters of a sampled net repeat (N + 1 distinct values per
  // direction), and a hit costs a fraction of a conversion.
  std::string_view text_of(double x) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    CachedText& c = cache_[(bits * 0x9e3779b97f4a7c15ull) >> (64 - kCacheBits)];
    if (c.size == 0 || c.bits != bits) {
      const auto r = std::to_chars(c.chars, c.chars + sizeof c.chars, x);
      c.size = static_cast<std::uint8_t>(r.ptr - c.chars);
      c.bits = bits;
    }
    return {c.chars, c.size};
  }
  static constexpr int kCacheBits = 8;
  struct CachedText {
    std::uint64_t bits = 0;
    std::uint8_t size = 0;  // 0: empty
    char chars[31];
  };

  std::string& out_;
  bool binary_;
  std::vector<CachedText> cache_ = std::vector<CachedText>(std::size_t{1} << kCacheBits);
};

}  // namespace

std::string vtp_text(const TriangleMesh& mesh, const SurfaceFields& fields, MeshFormat format,
                     const SharedNumberText* text, const std::vector<std::int32_t>* patch) {
  const Eigen::Index nv = mesh.V.rows(), nf = mesh.F.rows();
  if (fields.H.size() != nv || fields.K.size() != nv || fields.normal.rows() != nv || fields.uv.rows() != nv ||
      fields.regular.size() != nv)
    throw InternalError("write_vtp: fields do not match the mesh");
  if (text && text->vertices() != nv) throw InternalError("write_vtp: the shared number text is not of this mesh");
  const bool shared = text && format == MeshFormat::Ascii;
  if (patch && static_cast<Eigen::Index>(patch->size()) != nf) throw InternalError("write_vtp: patch ids do not match the mesh");
  using RowMat3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  using RowMat2 = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;
  const RowMat3 points = mesh.V, normals = fields.normal;
  const RowMat2 uv = fields.uv;
  std::vector<std::int32_t> connectivity(static_cast<size_t>(nf) * 3), offsets(static_cast<size_t>(nf));
  for (Eigen::Index t = 0; t < nf; ++t) {
    for (int c = 0; c < 3; ++c) connectivity[static_cast<size_t>(3 * t + c)] = mesh.F(t, c);
    offsets[static_cast<size_t>(t)] = static_cast<std::int32_t>(3 * (t + 1));
  }
  std::vector<std::uint8_t> regular(fields.regular.data(), fields.regular.data() + nv);

  std::string s;
  s.reserve(static_cast<size_t>(nv) * 200 + static_cast<size_t>(nf) * 40);
  s += "<?xml version=\"1.0\"?>\n<!-- bezierpde surface (FORMATS.md, surface.vtp) -->\n";
  s += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  s += "  <PolyData>\n    <Piece NumberOfPoints=\"" + std::to_string(nv) +
       "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(nf) +
       "\">\n";
  ArrayWriter w(s, format == MeshFormat::Binary);
  s += "      <PointData Scalars=\"mean_curvature\" Normals=\"Normals\" TCoords=\"uv\">\n";
  w.reals("Normals", normals.data(), static_cast<size_t>(nv) * 3, 3);
  if (shared)
    w.texts("mean_curvature", static_cast<size_t>(nv), 1, [&](size_t k) { return text->mean_curvature(static_cast<Eigen::Index>(k)); });
  else
    w.reals("mean_curvature", fields.H.data(), static_cast<size_t>(nv), 1);
  w.reals("gaussian_curvature", fields.K.data(), static_cast<size_t>(nv), 1);
  w.reals("uv", uv.data(), static_cast<size_t>(nv) * 2, 2);
  w.ints("UInt8", "regular", regular, 1);
  s += "      </PointData>\n";
  if (patch) {
    s += "      <CellData Scalars=\"patch\">\n";
    w.ints("Int32", "patch", *patch, 1);
    s += "      </CellData>\n";
  }
  s += "      <Points>\n";
  if (shared)
    w.texts("Points", static_cast<size_t>(nv) * 3, 3, [&](size_t k) {
      return text->vertex(static_cast<Eigen::Index>(k / 3), static_cast<int>(k % 3));
    });
  else
    w.reals("Points", points.data(), static_cast<size_t>(nv) * 3, 3);
  s += "      </Points>\n      <Polys>\n";
  w.ints("Int32", "connectivity", connectivity, 1);
  w.ints("Int32", "offsets", offsets, 1);
  s += "      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return s;
}

void write_vtp(const std::string& path, const TriangleMesh& mesh, const SurfaceFields& fields, MeshFormat format,
               const SharedNumberText* text, const std::vector<std::int32_t>* patch) {
  write_file_atomically(path, vtp_text(mesh, fields, format, text, patch));
}

}  // namespace bpde
