// The viscoelastic restitution ẽ(y) (physics/viscoelastic_restitution.hpp) against results that do
// not come from its code: the collision equation integrated here in its dimensional form by a
// plain fixed-step Runge–Kutta (another integrator, other variables, every physical constant
// explicit), and the closed form of the first coefficient of its series, C₁ (Schwager & Pöschel
// 1998), with the second, C₂ = 0.798544 (Ramírez, Pöschel, Brilliantov & Schwager 1999).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "physics/restitution_law.hpp"
#include "physics/viscoelastic_restitution.hpp"
#include "validation/viscoelastic_collision.hpp"

namespace granule {
namespace {

TEST(ViscoelasticRestitution, EqualsTheIntegratedCollisionAtEverySpeed) {
  const ViscoelasticMaterial m;
  const double radius = 0.25, mass = 0.5;  // two grains of diameter 1 and unit mass
  const double delta = 1.5 * m.dissipation * std::pow(hertz_rho(m, radius, mass), 0.4);
  for (const double speed : {1e-6, 1e-3, 0.1, 1.0, 10.0, 1e3, 1e5}) {
    const double expected = restitution_by_integration(m, radius, mass, speed);
    const double y = delta * std::pow(speed, 0.2);
    EXPECT_NEAR(viscoelastic_restitution(y), expected, 2e-7) << "g = " << speed << ", y = " << y;
    EXPECT_NEAR(integrate_viscoelastic_restitution(y), expected, 2e-7) << "g = " << speed;
  }
}

TEST(ViscoelasticRestitution, TableEqualsItsEquation) {
  for (double y = 1e-6; y < 30.0; y *= 1.37) {
    EXPECT_NEAR(viscoelastic_restitution(y), integrate_viscoelastic_restitution(y), 1e-9) << "y = " << y;
  }
  EXPECT_EQ(viscoelastic_restitution(0.0), 1.0);
}

TEST(ViscoelasticRestitution, SeriesCoefficientsOfTheLiterature) {
  const double c1 = std::tgamma(0.6) * std::sqrt(M_PI) / (std::pow(2.0, 0.2) * std::pow(5.0, 0.4) * std::tgamma(2.1));
  EXPECT_NEAR(c1, 1.15344, 1e-5);
  for (const double y : {1e-4, 3e-4}) {  // smaller y: the integration's 1e-13 drowns the y² term
    const double e = integrate_viscoelastic_restitution(y);
    EXPECT_NEAR((1.0 - e) / y, c1, 1.0 * y) << "y = " << y;
    EXPECT_NEAR((e - 1.0 + c1 * y) / (y * y), 0.798544, 0.01) << "y = " << y;
  }
}

TEST(ViscoelasticRestitution, FallsMonotonicallyFromOneAndStaysPositive) {
  double previous = 1.0;
  for (double y = 1e-4; y < 40.0; y *= 1.1) {
    const double e = viscoelastic_restitution(y);
    EXPECT_LT(e, previous) << "y = " << y;
    EXPECT_GT(e, 0.0) << "y = " << y;
    previous = e;
  }
}

// The law scales δ to the contact's own R_eff and m_eff: a grain of radius a₁ and mass m₁ against
// one of a₂, m₂, and against a wall of the same material, each equals the integrated collision of
// that contact.
TEST(RestitutionLaw, ViscoelasticConstantFollowsTheContactsRadiusAndMass) {
  const ViscoelasticMaterial m;
  const double sigma = 0.02;
  RestitutionLaw law;
  law.kind = RestitutionKind::kViscoelastic;
  law.reference_radius = 0.5 * sigma;
  law.viscoelastic_constant = 1.5 * m.dissipation * std::pow(hertz_rho(m, 0.25 * sigma, 0.5), 0.4);
  const double inf = std::numeric_limits<double>::infinity();
  struct Contact {
    double a1, m1, a2, m2, radius, mass;
  };
  for (const Contact& c : {Contact{0.5 * sigma, 1.0, 0.5 * sigma, 1.0, 0.25 * sigma, 0.5},
                           Contact{0.25 * sigma, 0.125, 0.5 * sigma, 1.0, sigma / 6.0, 1.0 / 9.0},
                           Contact{0.5 * sigma, 1.0, 0.0, inf, 0.5 * sigma, 1.0}}) {
    for (const double speed : {0.01, 1.0, 100.0}) {
      EXPECT_NEAR(law.at(0.5, speed, c.a1, c.m1, c.a2, c.m2), restitution_by_integration(m, c.radius, c.mass, speed), 2e-7)
          << "a = " << c.a1 << ", " << c.a2 << ", m = " << c.m1 << ", " << c.m2 << ", g = " << speed;
    }
  }
}

TEST(RestitutionLaw, ThresholdIsElasticBelowItsSpeedOnly) {
  RestitutionLaw law;
  law.kind = RestitutionKind::kThreshold;
  law.elastic_below = 0.3;
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(law.at(0.7, 0.2999, 0.5, 1.0, 0.5, 1.0), 1.0);
  EXPECT_EQ(law.at(0.7, 0.3, 0.5, 1.0, 0.5, 1.0), 0.7);
  EXPECT_EQ(law.at(0.7, 5.0, 0.5, 1.0, 0.0, inf), 0.7);
  RestitutionLaw constant;
  EXPECT_EQ(constant.at(0.7, 1e-9, 0.5, 1.0, 0.5, 1.0), 0.7);
}

}  // namespace
}  // namespace granule
