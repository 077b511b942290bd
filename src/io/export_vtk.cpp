#include "io/export_vtk.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/export_file.hpp"

namespace granule {

namespace {

static_assert(std::endian::native == std::endian::little, "the VTK writer declares LittleEndian");

// Appended raw data: each array is a UInt64 byte count followed by its bytes, referenced from the
// XML by its offset from the start of the block (after the '_' marker).
class AppendedArrays {
 public:
  // Registers an array and returns its XML element.
  std::string add(const std::string& attributes, std::vector<char> bytes) {
    const std::string element = fmt::format("<DataArray {} format=\"appended\" offset=\"{}\"/>\n", attributes, offset_);
    offset_ += sizeof(std::uint64_t) + bytes.size();
    blocks_.push_back(std::move(bytes));
    return element;
  }
  void write(std::ostream& out) const {
    out << "  <AppendedData encoding=\"raw\">\n_";
    for (const std::vector<char>& b : blocks_) {
      const std::uint64_t size = b.size();
      out.write(reinterpret_cast<const char*>(&size), sizeof size);
      out.write(b.data(), static_cast<std::streamsize>(b.size()));
    }
    out << "\n  </AppendedData>\n</VTKFile>\n";
  }

 private:
  std::size_t offset_ = 0;
  std::vector<std::vector<char>> blocks_;
};

template <typename T>
std::vector<char> bytes_of(const std::vector<T>& values) {
  std::vector<char> bytes(values.size() * sizeof(T));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

// (a, b, c) triples of three arrays; c = 0 when `c` is empty (2D).
std::vector<double> triples(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c) {
  std::vector<double> out(3 * a.size(), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[3 * i] = a[i];
    out[3 * i + 1] = b[i];
    if (!c.empty()) out[3 * i + 2] = c[i];
  }
  return out;
}

std::string time_field(double time) {
  return fmt::format("<FieldData><DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{}"
                     "</DataArray></FieldData>\n", time);
}

constexpr const char* kHeader =
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";

}  // namespace

void write_vtp_particles(const std::string& path, const ParticleState& p, double diameter, double time) {
  const std::size_t n = p.size();
  AppendedArrays data;
  std::string xml = fmt::format(fmt::runtime(kHeader), "PolyData") + "<PolyData>\n" + time_field(time);
  xml += fmt::format("<Piece NumberOfPoints=\"{0}\" NumberOfVerts=\"{0}\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                     "NumberOfPolys=\"0\">\n<PointData Vectors=\"velocity\" Scalars=\"radius\">\n", n);
  xml += data.add("type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\"", bytes_of(triples(p.vx, p.vy, p.vz)));
  std::vector<double> radius(n);
  for (std::size_t i = 0; i < n; ++i) radius[i] = 0.5 * p.diameter_of(i, diameter);
  xml += data.add("type=\"Float64\" Name=\"radius\"", bytes_of(radius));
  if (p.rough()) {
    const std::vector<double> none(p.dimension == 3 ? 0 : n, 0.0);
    const auto& wx = p.dimension == 3 ? p.wx : none;
    const auto& wy = p.dimension == 3 ? p.wy : none;
    xml += data.add("type=\"Float64\" Name=\"AngularVelocity\" NumberOfComponents=\"3\"", bytes_of(triples(wx, wy, p.wz)));
  }
  xml += "</PointData>\n<Points>\n";
  xml += data.add("type=\"Float64\" Name=\"position\" NumberOfComponents=\"3\"", bytes_of(triples(p.x, p.y, p.z)));
  xml += "</Points>\n<Verts>\n";
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  xml += data.add("type=\"Int64\" Name=\"connectivity\"", bytes_of(connectivity));
  xml += data.add("type=\"Int64\" Name=\"offsets\"", bytes_of(offsets));
  xml += "</Verts>\n</Piece>\n</PolyData>\n";
  StagedFile file(path);
  file.stream() << xml;
  data.write(file.stream());
  file.commit();
}

void write_vti_fields(const std::string& path, const FieldGrid& grid, const std::vector<NamedCellArray>& arrays, double time) {
  AppendedArrays data;
  // A 2D grid is one layer of cells of unit depth; a 3D grid has nz layers of its cell depth.
  const bool three_dimensional = grid.dimension == 3;
  const std::string extent = fmt::format("0 {} 0 {} 0 {}", grid.nx, grid.ny, three_dimensional ? grid.nz : 0);
  std::string xml = fmt::format(fmt::runtime(kHeader), "ImageData");
  xml += fmt::format("<ImageData WholeExtent=\"{}\" Origin=\"0 0 0\" Spacing=\"{} {} {}\">\n", extent, grid.cell_width(),
                     grid.cell_height(), three_dimensional ? grid.cell_depth() : 1.0);
  xml += time_field(time) + fmt::format("<Piece Extent=\"{}\">\n<CellData>\n", extent);
  for (const NamedCellArray& array : arrays) {
    if (array.values.size() != grid.cells()) throw std::invalid_argument("cell array " + array.name + " has the wrong size");
    xml += data.add(fmt::format("type=\"Float64\" Name=\"{}\"", array.name), bytes_of(array.values));
  }
  xml += "</CellData>\n</Piece>\n</ImageData>\n";
  StagedFile file(path);
  file.stream() << xml;
  data.write(file.stream());
  file.commit();
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames) {
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n<Collection>\n";
  for (const auto& [time, file] : frames) {
    xml += fmt::format("<DataSet timestep=\"{}\" part=\"0\" file=\"{}\"/>\n", time, file);
  }
  xml += "</Collection>\n</VTKFile>\n";
  write_file_atomically(path, xml);
}

}  // namespace granule
