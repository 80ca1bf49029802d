#pragma once
// A minimal PNG decoder (8-bit greyscale, RGB or RGBA, non-interlaced: what Chromium's
// --screenshot writes) over zlib, for the browser test.
#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace bpde::testing {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< width * height * 3, row-major from the top
  const std::uint8_t* at(int x, int y) const { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
};

inline Image decode_png(const std::string& file) {
  auto be32 = [&](size_t p) {
    return (static_cast<std::uint32_t>(static_cast<std::uint8_t>(file[p])) << 24) |
           (static_cast<std::uint32_t>(static_cast<std::uint8_t>(file[p + 1])) << 16) |
           (static_cast<std::uint32_t>(static_cast<std::uint8_t>(file[p + 2])) << 8) |
           static_cast<std::uint32_t>(static_cast<std::uint8_t>(file[p + 3]));
  };
  if (file.size() < 8 || file.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) throw std::runtime_error("not a PNG");
  Image img;
  int depth = 0, type = 0, interlace = 0;
  std::string idat;
  for (size_t p = 8; p + 8 <= file.size();) {
    const std::uint32_t len = be32(p);
    const std::string kind = file.substr(p + 4, 4);
    if (p + 12 + len > file.size()) throw std::runtime_error("truncated PNG");
    if (kind == "IHDR") {
      img.width = static_cast<int>(be32(p + 8));
      img.height = static_cast<int>(be32(p + 12));
      depth = static_cast<std::uint8_t>(file[p + 16]);
      type = static_cast<std::uint8_t>(file[p + 17]);
      interlace = static_cast<std::uint8_t>(file[p + 20]);
    } else if (kind == "IDAT") {
      idat.append(file, p + 8, len);
    } else if (kind == "IEND") {
      break;
    }
    p += 12 + len;
  }
  const int channels = type == 0 ? 1 : type == 2 ? 3 : type == 6 ? 4 : 0;
  if (depth != 8 || channels == 0 || interlace != 0) throw std::runtime_error("unsupported PNG layout");
  const size_t stride = static_cast<size_t>(img.width) * channels;
  std::vector<std::uint8_t> raw((stride + 1) * static_cast<size_t>(img.height));
  uLongf raw_size = raw.size();
  if (uncompress(raw.data(), &raw_size, reinterpret_cast<const Bytef*>(idat.data()), idat.size()) != Z_OK ||
      raw_size != raw.size())
    throw std::runtime_error("bad PNG data");
  std::vector<std::uint8_t> pix(stride * static_cast<size_t>(img.height)), prev(stride, 0);
  for (int y = 0; y < img.height; ++y) {
    const std::uint8_t filter = raw[y * (stride + 1)];
    const std::uint8_t* in = &raw[y * (stride + 1) + 1];
    std::uint8_t* out = &pix[y * stride];
    for (size_t x = 0; x < stride; ++x) {
      const int a = x >= static_cast<size_t>(channels) ? out[x - channels] : 0, b = prev[x],
                c = x >= static_cast<size_t>(channels) ? prev[x - channels] : 0;
      int v = in[x];
      switch (filter) {
        case 0:
          break;
        case 1:
          v += a;
          break;
        case 2:
          v += b;
          break;
        case 3:
          v += (a + b) / 2;
          break;
        case 4: {
          const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
          v += pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
          break;
        }
        default:
          throw std::runtime_error("bad PNG filter");
      }
      out[x] = static_cast<std::uint8_t>(v);
    }
    std::copy(out, out + stride, prev.begin());
  }
  img.rgb.resize(static_cast<size_t>(img.width) * img.height * 3);
  for (size_t k = 0; k < static_cast<size_t>(img.width) * img.height; ++k)
    for (int c = 0; c < 3; ++c) img.rgb[3 * k + c] = pix[k * channels + (channels == 1 ? 0 : c)];
  return img;
}

}  // namespace bpde::testing
