#include "observables/observables.hpp"

namespace granule {

// Each defined in its own file (<name>_observable.cpp).
template <int D>
std::unique_ptr<Observable<D>> make_fields_observable(const RunConfig&, const std::string&);
template <int D>
std::unique_ptr<Observable<D>> make_collision_statistics_observable(const RunConfig&, const std::string&);

template <int D>
std::vector<std::unique_ptr<Observable<D>>> configured_observables(const RunConfig& config, const std::string& out_dir) {
  static constexpr ObservableFactory<D> kFactories[] = {
      make_fields_observable<D>,                // [fields]: fields.h5
      make_collision_statistics_observable<D>,  // [collisions]: collisions.h5
  };
  std::vector<std::unique_ptr<Observable<D>>> observables;
  for (const ObservableFactory<D> make : kFactories) {
    if (std::unique_ptr<Observable<D>> observable = make(config, out_dir)) observables.push_back(std::move(observable));
  }
  return observables;
}

FieldGrid fields_grid(const RunConfig& config) {
  const SystemParams& s = config.system;
  if (s.dimension == 3) return default_field_grid_3d(s.length_x, s.length_y, s.length_z, s.particles);
  return FieldGrid{config.fields.cells.first, config.fields.cells.second, s.length_x, s.length_y};
}

std::optional<double> monodisperse_diameter(const RunConfig& config) {
  if (config.diameters.monodisperse()) return config.system.diameter;
  return std::nullopt;
}

template std::vector<std::unique_ptr<Observable<2>>> configured_observables(const RunConfig&, const std::string&);
template std::vector<std::unique_ptr<Observable<3>>> configured_observables(const RunConfig&, const std::string&);

}  // namespace granule
