// The registry of a run's observables (observables/observable.hpp): those its configuration switches
// on, in the order the driver calls them, and what several of them share.  A new observable is a
// file of its own in this folder defining its factory, and one line in observables.cpp.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/field_grid.hpp"
#include "io/config.hpp"
#include "observables/observable.hpp"

namespace granule {

// An observable of `config` writing into `out_dir`, or none when the configuration leaves it off.
template <int D>
using ObservableFactory = std::unique_ptr<Observable<D>> (*)(const RunConfig& config, const std::string& out_dir);

template <int D>
std::vector<std::unique_ptr<Observable<D>>> configured_observables(const RunConfig& config, const std::string& out_dir);

// The coarse-graining grid of [fields]: fields.cells in 2D; in 3D the default of ~20 spheres per
// cell.  The collision statistics measure the local density in the same cells.
FieldGrid fields_grid(const RunConfig& config);
// σ of a monodisperse run; none when polydisperse (observers then take each collision's σ_ij).
std::optional<double> monodisperse_diameter(const RunConfig& config);

}  // namespace granule
