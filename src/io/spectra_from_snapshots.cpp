#include "io/spectra_from_snapshots.hpp"

#include <filesystem>

#include "io/atomic_file.hpp"
#include "spectra/reciprocal_lattice.hpp"
#include "spectra/spectral_transforms.hpp"

namespace granule {

using namespace granule::spectra;
using namespace granule::spectra_file;

SpectraFromSnapshots::SpectraFromSnapshots(const SpectraRequest& request, const SnapshotRead& first)
    : request_(request), first_(first) {
  const SystemParams& system = first.metadata.system;
  box_ = ShearFrame{system.length_x, system.length_y, system.shear_velocity};
  transform_.max_mode = request.max_mode;
  transform_.method = request.method == "exact" ? SpectralMethod::exact : SpectralMethod::fast;
  transform_.subtract_shear_profile = request.subtract_shear;
  dk_ = request.dk.value_or(default_annulus_width(lattice_for_frame(box_, 0.0, system.dimension, system.length_z)));
  radius_ = complete_radius_at_any_strain(box_, request.max_mode, system.dimension, system.length_z);
  csv_path_ = !request.csv.empty() ? request.csv
                                   : std::filesystem::path(request.out).replace_extension("").string() + "_dominant.csv";
  l0_ = spectra::cluster_length(system);
  csv_ = dominant_csv_header();
  tallies_.resize(fields_of(system.dimension).size());
}

SpectraFromSnapshots::~SpectraFromSnapshots() = default;

FrameSpectra SpectraFromSnapshots::add_frame(std::int64_t index) {
  const SnapshotMetadata& metadata = first_.metadata;
  const int dimension = metadata.system.dimension;
  const SnapshotRead snapshot = index == 0 ? first_ : read_snapshot(request_.snapshots, index);
  const SnapshotFrame& frame = snapshot.frame;
  FrameSpectra result{frame.clock.time, frame.collisions_per_particle, {}};
  const ReciprocalLattice lattice = lattice_for_frame(box_, frame.shear_offset, dimension, metadata.system.length_z);
  const PowerMaps maps = power_maps(transform_fields(frame.particles, box_, lattice, transform_), request_.exclude_ky_axis);
  const AnnulusSpectrum annulus = annulus_sums(maps, dk_, radius_);
  if (!file_) {
    const SpectraFileSettings settings{request_.snapshots, request_.method, request_.subtract_shear, request_.exclude_ky_axis,
                                       request_.false_alarm};
    file_ = std::make_unique<SpectraFile>(request_.out, settings, metadata, transform_, dk_, annulus);
  }
  for (const FieldChoice& field : fields_of(dimension)) {
    const DominantMode& d =
        result.dominant.emplace_back(dominant_mode(maps, maps.*field.map, field.noise(maps), request_.false_alarm));
    csv_ += dominant_csv_row(index, frame, field.name, d, l0_);
  }
  file_->append(index, frame, maps, annulus, result.dominant, l0_);
  for (std::size_t f = 0; f < result.dominant.size(); ++f) tallies_[f].add(result.dominant[f], l0_);
  return result;
}

void SpectraFromSnapshots::publish() {
  write_file_atomically(csv_path_, csv_);
  file_->publish();
}

}  // namespace granule
