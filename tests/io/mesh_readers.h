#pragma once
// Minimal readers of what io/mesh_io and io/vtp_io write, written independently of the writers
// from the file formats themselves (PLY 1.0; VTK XML PolyData 1.0 with inline ascii or base64
// arrays and a UInt64 header), for the round-trip tests.
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace bpde::testing {

inline std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A PLY file with vertex properties (by name, as doubles) and triangles.
struct PlyData {
  std::string format;
  std::vector<std::string> names, types;  ///< vertex property names and types, in order
  std::map<std::string, std::vector<double>> vertex;
  std::vector<std::array<int, 3>> faces;
};

inline PlyData read_ply(const std::string& path) {
  const std::string text = read_all(path);
  const size_t end = text.find("end_header\n");
  if (end == std::string::npos) throw std::runtime_error("no end_header");
  std::istringstream header(text.substr(0, end));
  PlyData d;
  long nv = 0, nf = 0;
  std::string line, element;
  while (std::getline(header, line)) {
    std::istringstream w(line);
    std::string key;
    w >> key;
    if (key == "format") w >> d.format;
    if (key == "element") {
      w >> element;
      (element == "vertex" ? nv : nf) = [&] {
        long n;
        w >> n;
        return n;
      }();
    }
    if (key == "property" && element == "vertex") {
      std::string type, name;
      w >> type >> name;
      d.types.push_back(type);
      d.names.push_back(name);
    }
  }
  size_t pos = end + std::strlen("end_header\n");
  if (d.format == "ascii") {
    std::istringstream body(text.substr(pos));
    for (long v = 0; v < nv; ++v)
      for (const auto& name : d.names) {
        std::string token;
        body >> token;
        d.vertex[name].push_back(std::strtod(token.c_str(), nullptr));
      }
    for (long f = 0; f < nf; ++f) {
      int n;
      std::array<int, 3> t;
      body >> n >> t[0] >> t[1] >> t[2];
      if (n != 3) throw std::runtime_error("not a triangle");
      d.faces.push_back(t);
    }
  } else if (d.format == "binary_little_endian") {
    auto take = [&](void* out, size_t bytes) {
      if (pos + bytes > text.size()) throw std::runtime_error("short binary PLY");
      std::memcpy(out, text.data() + pos, bytes);
      pos += bytes;
    };
    for (long v = 0; v < nv; ++v)
      for (size_t k = 0; k < d.names.size(); ++k) {
        double value;
        if (d.types[k] == "float") {
          float f;
          take(&f, 4);
          value = f;
        } else if (d.types[k] == "double") {
          take(&value, 8);
        } else if (d.types[k] == "uchar") {
          std::uint8_t c;
          take(&c, 1);
          value = c;
        } else {
          throw std::runtime_error("unexpected type " + d.types[k]);
        }
        d.vertex[d.names[k]].push_back(value);
      }
    for (long f = 0; f < nf; ++f) {
      std::uint8_t n;
      take(&n, 1);
      if (n != 3) throw std::runtime_error("not a triangle");
      std::array<std::int32_t, 3> t;
      take(t.data(), 12);
      d.faces.push_back({t[0], t[1], t[2]});
    }
    if (pos != text.size()) throw std::runtime_error("trailing bytes in binary PLY");
  } else {
    throw std::runtime_error("unknown PLY format " + d.format);
  }
  return d;
}

inline std::vector<unsigned char> base64_decode(const std::string& s) {
  std::vector<unsigned char> out;
  unsigned buf = 0;
  int bits = 0;
  for (char c : s) {
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+')
      v = 62;
    else if (c == '/')
      v = 63;
    else
      continue;  // padding, white space
    buf = (buf << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buf >> bits) & 0xff));
    }
  }
  return out;
}

/// One DataArray of a VTP file.
struct VtpArray {
  std::string type, format;
  int components = 1;
  std::vector<double> values;
};

/// A VTK XML PolyData file: the Piece's attributes and its DataArrays by Name ("Points" for the
/// points when unnamed), plus the PointData attributes (Scalars, Normals, TCoords).
struct VtpData {
  std::map<std::string, std::string> piece, point_data;
  std::map<std::string, VtpArray> arrays;
};

inline std::map<std::string, std::string> xml_attributes(const std::string& tag) {
  std::map<std::string, std::string> a;
  size_t p = 0;
  while ((p = tag.find('=', p)) != std::string::npos) {
    size_t k = p;
    while (k > 0 && tag[k - 1] != ' ') --k;
    const size_t q1 = tag.find('"', p), q2 = tag.find('"', q1 + 1);
    a[tag.substr(k, p - k)] = tag.substr(q1 + 1, q2 - q1 - 1);
    p = q2 + 1;
  }
  return a;
}

inline VtpData read_vtp(const std::string& path) {
  const std::string text = read_all(path);
  VtpData d;
  auto tag_at = [&](const std::string& name) {
    const size_t p = text.find("<" + name + " ");
    if (p == std::string::npos) throw std::runtime_error("no <" + name + ">");
    return text.substr(p, text.find('>', p) - p);
  };
  if (xml_attributes(tag_at("VTKFile"))["type"] != "PolyData") throw std::runtime_error("not PolyData");
  d.piece = xml_attributes(tag_at("Piece"));
  d.point_data = xml_attributes(tag_at("PointData"));
  size_t p = 0;
  while ((p = text.find("<DataArray ", p)) != std::string::npos) {
    const size_t close = text.find('>', p), end = text.find("</DataArray>", close);
    auto attr = xml_attributes(text.substr(p, close - p));
    VtpArray a;
    a.type = attr["type"];
    a.format = attr["format"];
    if (attr.count("NumberOfComponents")) a.components = std::stoi(attr["NumberOfComponents"]);
    const std::string body = text.substr(close + 1, end - close - 1);
    if (a.format == "ascii") {
      std::istringstream in(body);
      std::string token;
      while (in >> token) a.values.push_back(std::strtod(token.c_str(), nullptr));
    } else if (a.format == "binary") {
      const std::vector<unsigned char> bytes = base64_decode(body);
      std::uint64_t n;
      std::memcpy(&n, bytes.data(), 8);
      if (n + 8 != bytes.size()) throw std::runtime_error("VTP block size mismatch");
      const unsigned char* q = bytes.data() + 8;
      const size_t width = a.type == "Float64" ? 8 : a.type == "UInt8" ? 1 : 4;
      for (size_t k = 0; k < n / width; ++k, q += width) {
        if (a.type == "Float32") {
          float f;
          std::memcpy(&f, q, 4);
          a.values.push_back(f);
        } else if (a.type == "Float64") {
          double f;
          std::memcpy(&f, q, 8);
          a.values.push_back(f);
        } else if (a.type == "Int32") {
          std::int32_t i;
          std::memcpy(&i, q, 4);
          a.values.push_back(i);
        } else if (a.type == "UInt8") {
          a.values.push_back(*q);
        } else {
          throw std::runtime_error("unexpected type " + a.type);
        }
      }
    } else {
      throw std::runtime_error("unexpected format " + a.format);
    }
    d.arrays[attr.count("Name") ? attr["Name"] : "Points"] = a;
    p = end;
  }
  return d;
}

}  // namespace bpde::testing
