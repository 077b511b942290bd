// A rendered picture as plain pixels (8-bit RGB per pixel, rows from the top), and its PNG file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace granule::render {

struct Pixel {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
};

struct RasterImage {
  int width = 0;
  int height = 0;
  std::vector<Pixel> pixels;  // row-major, row 0 at the top of the picture

  const Pixel& at(int column, int row) const {
    return pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)];
  }
};

// Writes `image` as PNG to `path` atomically (temporary name, then rename).  Throws
// std::runtime_error naming the path on failure.
void write_png(const RasterImage& image, const std::string& path);

}  // namespace granule::render
