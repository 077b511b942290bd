#include "render/raster_image.hpp"

#include <cairo.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "io/io_error.hpp"

namespace granule::render {

void write_png(const RasterImage& image, const std::string& path) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.width, image.height);
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int row = 0; row < image.height; ++row) {
    auto* line = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(row) * stride);
    for (int column = 0; column < image.width; ++column) {
      const Pixel& p = image.at(column, row);
      line[column] = (std::uint32_t{p.r} << 16) | (std::uint32_t{p.g} << 8) | std::uint32_t{p.b};
    }
  }
  cairo_surface_mark_dirty(surface);
  const std::string partial = path + ".partial";
  const cairo_status_t status = cairo_surface_write_to_png(surface, partial.c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    std::filesystem::remove(partial);
    const std::string message = "cannot write " + path + ": " + cairo_status_to_string(status);
    if (status == CAIRO_STATUS_WRITE_ERROR) throw IoError(message);  // disk full, vanished directory
    throw std::runtime_error(message);
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::filesystem::remove(partial);
    throw io_error("cannot rename " + partial + " to " + path, error);
  }
}

}  // namespace granule::render
