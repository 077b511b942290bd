// granule.theory: the closed-form results behind `granule theory
// haff|steady-shear|free-stability` (src/theory, docs/theory.md).  The scalar
// formulas accept NumPy arrays (vectorised element by element); they are the
// formulas as written, without the range checks of the command line.
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings/bindings.hpp"
#include "theory/free_gas_stability.hpp"
#include "theory/haff.hpp"
#include "theory/hard_spheres.hpp"
#include "theory/homogeneous_cooling.hpp"
#include "theory/kinetic_scales.hpp"
#include "theory/steady_shear.hpp"

namespace granule::bindings {

namespace py = pybind11;
namespace th = granule::theory;

namespace {

py::dict steady_shear(double restitution, double shear_rate, double diameter, double area_fraction) {
  py::dict out;
  out["tan_fit"] = th::steady_shear_temperature_tan_fit(restitution, shear_rate, diameter, area_fraction);
  out["jenkins_richman"] =
      th::steady_shear_temperature_jenkins_richman(restitution, shear_rate, diameter, area_fraction);
  out["kinetic"] = th::steady_shear_temperature_kinetic(restitution, shear_rate, diameter, area_fraction);
  return out;
}

void bind_cooling(py::module_& t) {
  t.def("haff_temperature", py::vectorize(th::haff_temperature), py::arg("t"), py::arg("T0"), py::arg("t0"),
        "T(t) = T0/(1 + t/t0)², Haff's law (2.10)");
  t.def("haff_time_disks", py::vectorize(th::haff_time_disks), py::arg("T0"), py::arg("restitution"),
        py::arg("diameter"), py::arg("area_fraction"), py::arg("contact_value") = 1.0,
        "t0 = √π σ/(2 χ ν ε √T0) of dilute inelastic disks (Boltzmann), ε = 1 "
        "− ẽ²");
  t.def("haff_temperature_after_collisions", py::vectorize(th::haff_temperature_after_collisions), py::arg("c"),
        py::arg("T0"), py::arg("restitution"), "T(c) = T0 exp(−(1 − ẽ²) c), c = collisions per particle");
  t.def("haff_collisions_per_particle", py::vectorize(th::haff_collisions_per_particle), py::arg("t"), py::arg("t0"),
        py::arg("restitution"), "c(t) = (2/ε) ln(1 + t/t0) of a Haff-cooling disk gas");
  t.def("sonine_a2", py::vectorize(th::sonine_a2), py::arg("restitution"), py::arg("dimension"),
        "second Sonine coefficient a2 of the homogeneous cooling state (van "
        "Noije & Ernst 1998)");
  t.def("homogeneous_cooling_rate", py::vectorize(th::homogeneous_cooling_rate), py::arg("dimension"),
        py::arg("restitution"), py::arg("maxwellian_collision_frequency"), py::arg("a2"),
        "ζ of dT/dt = −ζT with the Sonine correction");
  t.def("homogeneous_cooling_time", py::vectorize(th::homogeneous_cooling_time), py::arg("dimension"),
        py::arg("restitution"), py::arg("maxwellian_collision_frequency_at_T0"), py::arg("a2"),
        "Haff time t0 = 2/ζ(T0)");
  t.def("temperature_after_collisions", py::vectorize(th::temperature_after_collisions), py::arg("dimension"),
        py::arg("collisions_per_particle"), py::arg("T0"), py::arg("restitution"), py::arg("a2"),
        "T(c) = T0 exp(−2 f c), f the energy lost per collision with the "
        "Sonine correction");
  t.def("free_gas_eigenvalues", &th::free_gas_eigenvalues, py::arg("K"), py::arg("eps"),
        "eigenvalues of the linearised Jenkins–Richman equations of the "
        "cooling gas (2.28), K = k l0, by decreasing real part");
  t.def("free_gas_shear_eigenvalue", py::vectorize(th::free_gas_shear_eigenvalue), py::arg("K"), py::arg("eps"),
        "the shear-mode eigenvalue (2.35)");
}

void bind_scales(py::module_& t) {
  t.def("inelasticity", py::vectorize(th::inelasticity), py::arg("restitution"), "ε = 1 − ẽ²");
  t.def("mean_free_path", py::vectorize(th::mean_free_path), py::arg("diameter"), py::arg("area_fraction"),
        "the thesis's l = πσ/(8ν) of disks");
  t.def("boltzmann_mean_free_path", py::vectorize(th::boltzmann_mean_free_path), py::arg("diameter"),
        py::arg("area_fraction"), "1/(2√2 nσ) = l/√2 of dilute disks");
  t.def("disk_collision_frequency", py::vectorize(th::disk_collision_frequency), py::arg("temperature"),
        py::arg("diameter"), py::arg("area_fraction"), py::arg("contact_value") = 1.0,
        "ω = 8νχ√T/(√π σ) of one disk in a Maxwellian gas");
  t.def("henderson_contact_value", py::vectorize(th::henderson_contact_value), py::arg("area_fraction"),
        "χ(ν) = (1 − 7ν/16)/(1 − ν)² for hard disks");
  t.def("cluster_separation", py::vectorize(th::cluster_separation), py::arg("restitution"), py::arg("diameter"),
        py::arg("area_fraction"), "L0 = l/√(1 − ẽ²), thesis (1.1)");
  t.def("hard_sphere_collision_frequency", py::vectorize(th::hard_sphere_collision_frequency), py::arg("dimension"),
        py::arg("number_density"), py::arg("diameter"), py::arg("contact_value"), py::arg("temperature"),
        py::arg("mass") = 1.0, "ω of one disk (d = 2) or sphere (d = 3) in a Maxwellian gas");
  t.def("hard_sphere_contact_value", py::vectorize(th::hard_sphere_contact_value), py::arg("dimension"),
        py::arg("packing_fraction"), "χ: Henderson (disks) or Carnahan–Starling (spheres)");
  t.def("number_density", py::vectorize(th::number_density), py::arg("dimension"), py::arg("packing_fraction"),
        py::arg("diameter"));
}

void bind_shear(py::module_& t) {
  t.def("steady_shear", &steady_shear, py::arg("restitution"), py::arg("shear_rate"), py::arg("diameter"),
        py::arg("area_fraction"),
        R"doc(
Steady temperature T̄ of simply sheared dilute disks (shear rate γ = U/L_y) as a dict:
tan_fit (the thesis's fit (3.1)), jenkins_richman (the dilute limit (3.2)) and kinetic (T0 of (4.5)).
)doc");
  t.def("diameter_for_area_fraction", &th::diameter_for_area_fraction, py::arg("area_fraction"), py::arg("particles"),
        py::arg("box_x"), py::arg("box_y"), "σ = √(4ν L_x L_y/(πN))");
}

}  // namespace

void bind_theory(py::module_& m) {
  py::module_ t = m.def_submodule("theory",
                                  "Closed-form and linear-stability results of "
                                  "src/theory (docs/theory.md)");
  bind_cooling(t);
  bind_scales(t);
  bind_shear(t);
}

}  // namespace granule::bindings
