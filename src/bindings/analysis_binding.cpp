// The analyses of saved configurations as functions on NumPy arrays:
// coarse-grained cell fields (analysis/cell_fields.hpp, thesis §1.4.3),
// Fourier spectra of mass and momentum (spectra/, thesis §2.2 and §3.2.1) and the
// spin correlation of neighbouring rough grains (analysis/spin_correlation.hpp, Fig C.4), the
// computations behind `granule analyze fields|spectra|spins`.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <stdexcept>

#include "analysis/cell_fields.hpp"
#include "analysis/spin_correlation.hpp"
#include "driver/run_beginnings.hpp"
#include "bindings/bindings.hpp"
#include "bindings/input_checks.hpp"
#include "bindings/numpy_arrays.hpp"
#include "io/input_ranges.hpp"
#include "spectra/dominant_mode.hpp"
#include "spectra/power_spectra.hpp"
#include "spectra/spectra_memory.hpp"
#include "spectra/spectral_transforms.hpp"

namespace granule::bindings {

namespace py = pybind11;

namespace {

// Coarse-graining cells per axis: those of `granule analyze fields --cells`.
constexpr int kMaxFieldCells = 1 << 14;

// An integer argument in [low, high]: a Python int or anything with __index__ (NumPy integers),
// not a float.  `name` names it in errors.
int integer_argument(py::handle value, const std::string& name, int low, int high) {
  const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!index) {
    PyErr_Clear();
    throw py::type_error(fmt::format("{} must be an integer, not {}", name, type_name(value)));
  }
  int overflow = 0;
  const long long result = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  if (overflow != 0 || result < low || result > high) {
    throw py::value_error(fmt::format("{} = {}: must be an integer in [{}, {}]", name,
                                      overflow != 0 ? "an integer beyond 64 bits" : std::to_string(result), low, high));
  }
  return static_cast<int>(result);
}

// A finite double in `range`, else ValueError naming it.
double checked(double value, const NumberRange& range, const char* name) {
  if (!range.contains(value)) throw py::value_error(fmt::format("{} = {}: must be in {}", name, value, range.text()));
  return value;
}

FieldGrid field_grid(const py::object& cells, const Box& box, int dimension, std::size_t particles) {
  const auto n = static_cast<std::int64_t>(particles);
  if (cells.is_none()) {
    return dimension == 3 ? default_field_grid_3d(box.length_x, box.length_y, box.length_z, n)
                          : default_field_grid(box.length_x, box.length_y, n);
  }
  if (!py::isinstance<py::sequence>(cells) || py::isinstance<py::str>(cells)) {
    throw py::type_error(fmt::format("cells must be a sequence of integers, not {}", type_name(cells)));
  }
  const py::sequence counts = cells;
  if (static_cast<int>(py::len(counts)) != dimension)
    throw py::value_error("cells must be (nx, ny) in 2D, (nx, ny, nz) in 3D");
  int c[3] = {1, 1, 1};
  for (int a = 0; a < dimension; ++a) {
    c[a] = integer_argument(counts[static_cast<std::size_t>(a)], fmt::format("cells[{}]", a), 1, kMaxFieldCells);
  }
  if (dimension == 3) return {c[0], c[1], box.length_x, box.length_y, c[2], box.length_z, 3};
  return {c[0], c[1], box.length_x, box.length_y};
}

// A per-cell field as an array indexed [iy, ix] (2D) or [iz, iy, ix] (3D).
Array cell_array(const std::vector<double>& values, const FieldGrid& grid) {
  std::vector<py::ssize_t> shape = {grid.ny, grid.nx};
  if (grid.dimension == 3) shape.insert(shape.begin(), grid.nz);
  Array array(shape);
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

// The shear of the frame: U a speed (0 or within the engine's range), Δ within [0, L_x] as
// Simulation.shear_offset gives it.
ShearFrame shear_frame(const Box& box, double shear_velocity, double shear_offset) {
  if (shear_velocity != 0.0 && !kSpeedRange.contains(std::abs(shear_velocity))) {
    throw py::value_error(fmt::format("shear_velocity = {}: |U| must be 0 or in {}", shear_velocity, kSpeedRange.text()));
  }
  checked(shear_offset, NumberRange{0.0, box.length_x}, "shear_offset");
  return {box.length_x, box.length_y, shear_velocity};
}

py::dict cell_fields(const py::object& positions, const py::object& velocities, const py::object& box,
                     const py::object& cells, const py::object& masses, double shear_velocity, double shear_offset,
                     bool subtract_shear_profile) {
  const ConfigurationArrays arrays = configuration_arrays(positions, velocities, masses);
  const Box lengths = box_argument(box, arrays.dimension);
  const ShearFrame frame = shear_frame(lengths, shear_velocity, shear_offset);
  const FieldGrid grid = field_grid(cells, lengths, arrays.dimension, arrays.particles);
  // One set of moments, the fields computed from it and their NumPy copies (spins are not summed:
  // no moment of inertia is given).
  const bool with_masses = !arrays.masses.is_none();
  driver::require_memory(static_cast<double>(arrays.particles) * kAnalysisBytesPerParticle +
                             cell_moments_bytes(grid, with_masses, false) + 2.0 * cell_fields_bytes(grid, false),
                         fmt::format("cell_fields of N = {} on {} cells", arrays.particles, grid.cells()));
  const ParticleState state = particle_state(arrays, lengths);
  CellMoments moments(grid);
  moments.add(state, frame, subtract_shear_profile);
  const CellFields fields = fields_from_moments(moments, frame, shear_offset, subtract_shear_profile);
  py::dict out;
  for_each_field(fields,
                 [&](const char* name, const std::vector<double>& values) { out[name] = cell_array(values, grid); });
  return out;
}

py::dict dominant(const spectra::DominantMode& mode) {
  py::dict out;
  out["k"] = mode.k;
  out["kx"] = mode.kx;
  out["ky"] = mode.ky;
  out["kz"] = mode.kz;
  out["angle_deg"] = mode.angle_deg;
  out["length"] = mode.length;
  out["power"] = mode.power;
  out["power_over_ideal_gas"] = mode.power_over_ideal_gas;
  out["independent_modes"] = mode.independent_modes;
  out["noise_p_value"] = mode.noise_p_value;
  out["noise_threshold"] = mode.noise_threshold;
  out["significant"] = mode.significant;
  return out;
}

py::dict power_spectra(const py::object& positions, const py::object& velocities, const py::object& box,
                       const py::object& masses, double shear_velocity, double shear_offset,
                       std::optional<int> max_mode, const std::string& method, bool subtract_shear_profile,
                       bool exclude_ky_axis, std::optional<double> dk) {
  const ConfigurationArrays arrays = configuration_arrays(positions, velocities, masses);
  const int d = arrays.dimension;
  const Box lengths = box_argument(box, d);
  const ShearFrame frame = shear_frame(lengths, shear_velocity, shear_offset);
  if (method != "fast" && method != "exact") throw std::invalid_argument("method must be \"fast\" or \"exact\"");
  spectra::TransformOptions options;
  options.max_mode = max_mode.value_or(d == 3 ? 32 : 64);  // the defaults of `granule analyze spectra`
  if (options.max_mode < 1 || options.max_mode > (d == 3 ? 256 : 2048)) {
    throw std::invalid_argument("max_mode must be in [1, 2048] in 2D, [1, 256] in 3D");
  }
  options.method = method == "exact" ? spectra::SpectralMethod::exact : spectra::SpectralMethod::fast;
  options.subtract_shear_profile = subtract_shear_profile;
  const spectra::ReciprocalLattice lattice = spectra::lattice_for_frame(frame, shear_offset, d, lengths.length_z);
  const double width =
      dk ? checked(*dk, NumberRange{0.0, kUnbounded, true, true}, "dk")
         : spectra::default_annulus_width(spectra::lattice_for_frame(frame, 0.0, d, lengths.length_z));
  const double radius = lattice.complete_radius(options.max_mode);
  const double annuli = spectra::annulus_count(width, radius);
  if (!(annuli <= spectra::kMaxAnnuli)) {
    throw py::value_error(fmt::format("dk = {}{}: more than 2^32 annuli up to k = {}: choose a wider dk", width,
                                      dk ? "" : " (the default, 2π/L_max)", radius));
  }
  // The NumPy copies of the maps below are made once the transforms are freed, within the peak
  // that spectra_bytes counts.
  driver::require_memory(static_cast<double>(arrays.particles) * kAnalysisBytesPerParticle +
                             spectra::spectra_bytes(arrays.particles, d, options, annuli),
                         fmt::format("spectra of N = {} with max_mode = {}", arrays.particles, options.max_mode));
  const ParticleState state = particle_state(arrays, lengths);
  const spectra::PowerMaps maps =
      spectra::power_maps(spectra::transform_fields(state, frame, lattice, options), exclude_ky_axis);
  const spectra::AnnulusSpectrum annulus = spectra::annulus_sums(maps, width, radius);
  py::dict out;
  out["dk"] = annulus.dk;
  out["k"] = read_only_vector(annulus.k);
  out["modes"] = annulus.modes;
  out["density"] = read_only_vector(annulus.density);
  out["momentum_x"] = read_only_vector(annulus.momentum_x);
  out["momentum_y"] = read_only_vector(annulus.momentum_y);
  if (d == 3) out["momentum_z"] = read_only_vector(annulus.momentum_z);
  out["momentum"] = read_only_vector(annulus.momentum);
  out["ideal_density"] = maps.ideal_density;
  out["ideal_momentum"] = maps.ideal_momentum();
  out["dominant_density_mode"] = dominant(spectra::dominant_mode(maps, maps.density, maps.ideal_density));
  py::dict mode_maps;
  mode_maps["kx"] = read_only_vector(maps.kx);
  mode_maps["ky"] = read_only_vector(maps.ky);
  if (d == 3) mode_maps["kz"] = read_only_vector(maps.kz);
  mode_maps["density"] = read_only_vector(maps.density);
  mode_maps["momentum"] = read_only_vector(maps.momentum);
  out["maps"] = mode_maps;
  return out;
}

py::dict spin_correlation(const py::object& positions, const py::object& spins, const py::object& box, double diameter,
                          const py::object& diameters, double shear_offset, const py::object& walls, double max_distance,
                          int bins, double contact_shell) {
  // The positions are checked as cell_fields checks them; the velocities are not used.
  const ConfigurationArrays arrays = configuration_arrays(positions, positions, py::none());
  const int d = arrays.dimension;
  const Box lengths = box_argument(box, d);
  checked(shear_offset, NumberRange{0.0, lengths.length_x}, "shear_offset");
  checked(diameter, NumberRange{0.0, kUnbounded, true, true}, "diameter");
  driver::require_memory(static_cast<double>(arrays.particles) * kAnalysisBytesPerParticle,
                         fmt::format("spin_correlation of N = {}", arrays.particles));
  ParticleState state = particle_state(arrays, lengths);
  std::vector<std::vector<double>> w = particle_columns(spins, "spins", arrays.particles, d == 3 ? 3 : 1, false);
  for (int k = 0; k < state.spin_components(); ++k) state.spin(k) = std::move(w[static_cast<std::size_t>(k)]);
  if (!diameters.is_none()) {
    state.diameter = std::move(particle_columns(diameters, "diameters", arrays.particles, 1, true)[0]);
    state.mass.assign(arrays.particles, 1.0);
  }
  PairImages images;
  images.length = {lengths.length_x, lengths.length_y, lengths.length_z};
  images.shear_offset = shear_offset;
  if (!walls.is_none()) {
    const auto axes = walls.cast<std::vector<bool>>();
    if (static_cast<int>(axes.size()) != d) throw py::value_error(fmt::format("walls must hold {} booleans, one per axis", d));
    for (int a = 0; a < d; ++a) images.walls[static_cast<std::size_t>(a)] = axes[static_cast<std::size_t>(a)];
    if (images.walls[1]) images.shear_offset = 0.0;  // y walls replace the sheared images
  }
  SpinCorrelationSettings settings;
  settings.max_distance = max_distance;
  settings.bins = bins;
  settings.contact_shell = contact_shell;
  const SpinPairSums sums = spin_pair_sums(state, images, diameter, settings);  // std::invalid_argument → ValueError
  py::dict out;
  const std::vector<double> edges = spin_correlation_edges(settings);
  std::vector<double> centres(static_cast<std::size_t>(bins));
  for (std::size_t k = 0; k < centres.size(); ++k) centres[k] = 0.5 * (edges[k] + edges[k + 1]);
  out["r_edges"] = read_only_vector(edges);
  out["r"] = read_only_vector(centres);
  const char* suffixes[kPairDirections] = {"", "_flow", "_gradient"};
  for (std::size_t direction = 0; direction < kPairDirections; ++direction) {
    std::vector<double> c(centres.size());
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = sums.correlation(static_cast<PairDirection>(direction), k);
    out[py::str(std::string("C") + suffixes[direction])] = read_only_vector(c);
    out[py::str(std::string("pairs") + suffixes[direction])] = read_only_vector(sums.pairs[direction]);
  }
  out["C_contact"] = sums.contact_correlation();
  out["contact_pairs"] = sums.contact_pairs;
  out["mean_spin"] = d == 3 ? py::cast(std::vector<double>(sums.mean_spin.begin(), sums.mean_spin.end())) : py::cast(sums.mean_spin[2]);
  out["spin_variance"] = sums.spin_variance;
  return out;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("cell_fields", &cell_fields, py::arg("positions"), py::arg("velocities"), py::arg("box"),
        py::arg("cells") = py::none(), py::arg("masses") = py::none(), py::arg("shear_velocity") = 0.0,
        py::arg("shear_offset") = 0.0, py::arg("subtract_shear_profile") = false, R"doc(
Coarse-grained fields of thesis §1.4.3 (granule analyze fields) of one configuration: N × d lab
positions in [0, L) and velocities, box (L_x, L_y[, L_z]), cells (nx, ny[, nz]) (default: about
20 particles a cell), optional masses (N,) for mass-weighted V, T and stresses.  Lees–Edwards:
shear_velocity U and shear_offset Δ give the vorticity's neighbours across y; with
subtract_shear_profile the velocities are taken relative to u(y) = γ(y − L_y/2).  Returns name →
array [iy, ix] (2D) or [iz, iy, ix] (3D): count, density, velocity_x, velocity_y, temperature
(T per degree of freedom, eq 1.3), kinetic_xx/xy/yy, pressure_kinetic, vorticity,
heat_flux_kinetic_x/y (and the z components in 3D), the names of fields.h5.

Inputs are checked before anything is copied: arrays of real numbers (TypeError otherwise), finite
velocities, positive masses, positions with 0 ≤ x ≤ L per axis, box lengths in [1e-30, 1e30]
within a factor 1e9 of one another, cells integers in [1, 16384], a finite U and Δ in [0, L_x]
(ValueError, naming the first bad entry); a grid or copy larger than the available memory raises
MemoryError.
)doc");
  m.def("spectra", &power_spectra, py::arg("positions"), py::arg("velocities"), py::arg("box"),
        py::arg("masses") = py::none(), py::arg("shear_velocity") = 0.0, py::arg("shear_offset") = 0.0,
        py::arg("max_mode") = py::none(), py::arg("method") = "fast", py::arg("subtract_shear_profile") = false,
        py::arg("exclude_ky_axis") = false, py::arg("dk") = py::none(), R"doc(
Fourier spectra of mass and momentum (granule analyze spectra, docs/spectra.md) of one
configuration on the allowed reciprocal lattice (sheared by shear_offset Δ under Lees–Edwards):
the annulus (3D: shell) sums R(k), P_x(k), P_y(k), P(k) of width dk (default 2π/L_max) against
ring centres k, with the number of modes per ring, the ideal-gas levels ⟨R⟩ and ⟨P⟩, the dominant
density mode (its |k|, angle, length 2π/|k| and significance) and the mode maps.  max_mode M
(default 64 in 2D, 32 in 3D) bounds the modes |l|, |m| (, |n|) ≤ M; method "fast" (gridded FFT,
~1e-7 relative) or "exact" (direct sums).

The arrays, box, U and Δ are checked as by cell_fields; dk must be a finite wavenumber > 0 that
makes at most 2^32 annuli.  FFT grids, mode maps and copies larger than the available memory
raise MemoryError before they are allocated.
)doc");
  m.def("spin_correlation", &spin_correlation, py::arg("positions"), py::arg("spins"), py::arg("box"),
        py::arg("diameter") = 1.0, py::arg("diameters") = py::none(), py::arg("shear_offset") = 0.0,
        py::arg("walls") = py::none(), py::arg("max_distance") = 3.0, py::arg("bins") = 20, py::arg("contact_shell") = 0.1,
        R"doc(
Spin correlation of neighbouring rough grains (granule analyze spins, thesis Fig C.4) of one
configuration: N × d lab positions in [0, L), spins ω_z (N,) for disks or ω (N, 3) for spheres
(Simulation.spins), box (L_x, L_y[, L_z]), the diameter σ (or per-grain diameters (N,)), the
Lees–Edwards offset Δ of the images above (Simulation.shear_offset) and walls, one bool per axis
(no images across a wall; y walls drop Δ).  With δω = ω − ⟨ω⟩ (the configuration's mean spin, ≈ −γ/2
under shear, removed) and r = |r_ij|/σ_ij, returns C(r) = ⟨δω_i·δω_j⟩_pairs / ⟨|δω|²⟩ in `bins`
bins over [1, max_distance] ("r_edges", "r", "C", "pairs"), the same for pairs along the flow
(|Δx| largest: "C_flow", "pairs_flow") and the gradient ("C_gradient", "pairs_gradient"),
"C_contact" over the pairs with r < 1 + contact_shell and "contact_pairs", "mean_spin",
"spin_variance".  Bins without pairs hold NaN.  Positions and box are checked as by cell_fields;
spins finite, diameters positive; a periodic length below 2 · max_distance · σ_max, or
max_distance ≤ 1 + contact_shell, raises ValueError.
)doc");
}

}  // namespace granule::bindings
