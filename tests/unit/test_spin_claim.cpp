// The Fig C.4 claim of `granule reproduce appendix-c` (reproduce/rough_shear.hpp) read from real
// spins.h5 files written by io/spins_file.hpp: the claim is a sign claim, so anticorrelated neighbours
// agree, correlated ones disagree, a contact value within 2σ of zero resolves no sign (the verdict rule
// says why), and a missing file is said.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/spins_file.hpp"
#include "reproduce/rough_shear.hpp"

namespace granule::reproduce {
namespace {

namespace fs = std::filesystem;

// A run directory whose spins.h5 holds one frame per contact value given (100 contact pairs each).
PointOutputs run_with_contact_values(const std::string& name, const std::vector<double>& contact) {
  const fs::path dir = fs::temp_directory_path() / ("granule_test_spin_claim_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  SnapshotMetadata metadata;
  metadata.system.roughness.rough = true;
  metadata.boundary = "lees-edwards";
  SpinCorrelationSettings settings;
  settings.bins = 4;
  SpinsFile file((dir / "spins.h5").string(), "snapshots.h5", metadata, settings);
  SpinCorrelationAverage average;
  for (std::size_t k = 0; k < contact.size(); ++k) {
    SpinPairSums sums;
    for (std::size_t d = 0; d < kPairDirections; ++d) {
      sums.pairs[d].assign(4, 10.0);
      sums.products[d].assign(4, 10.0 * contact[k]);
    }
    sums.contact_pairs = 100.0;
    sums.contact_products = 100.0 * contact[k];
    file.append(static_cast<std::int64_t>(k), SnapshotFrame{}, sums);
    average.add(sums);
  }
  file.publish(average);
  PointOutputs p;
  p.name = name;
  p.directory = dir.string();
  p.status = "finished";
  p.samples.resize(1);
  return p;
}

Claim spin_claim(const GroupOutputs& group) {
  StudyOutcome out;
  add_spin_claim(group, out);
  EXPECT_EQ(out.claims.size(), 1u);
  EXPECT_EQ(out.figures.size(), 1u);
  return out.claims.front();
}

TEST(SpinClaim, AnticorrelatedNeighboursAgree) {
  const Claim c = spin_claim({run_with_contact_values("anti", {-0.05, -0.07, -0.06, -0.04})});
  EXPECT_NEAR(c.measured, -0.055, 1e-12);
  EXPECT_EQ(judge(c), Verdict::agrees);
}

TEST(SpinClaim, CorrelatedNeighboursDisagree) {
  const Claim c = spin_claim({run_with_contact_values("aligned", {0.05, 0.07, 0.06, 0.04})});
  EXPECT_EQ(judge(c), Verdict::disagrees) << c.measured << " ± " << c.error;
}

TEST(SpinClaim, ZeroWithinTwoSigmaResolvesNoSign) {
  const Claim c = spin_claim({run_with_contact_values("zero", {-0.1, 0.08, -0.05, 0.06})});
  EXPECT_EQ(c.tolerance_kind, ToleranceKind::sign);
  EXPECT_TRUE(c.unresolvable.empty());  // the rule, not the study, finds the sign unresolved
  const Judgement j = judgement(c);
  EXPECT_EQ(j.verdict, Verdict::not_resolvable);
  EXPECT_NE(j.reason.find("within 2σ"), std::string::npos) << j.reason;
}

TEST(SpinClaim, AnticorrelationWithinTwoSigmaOfZeroDoesNotAgree) {
  // The mean is negative but ±2σ reaches above zero: a band [−1, 0] would have agreed.
  const Claim c = spin_claim({run_with_contact_values("weak", {-0.06, 0.03, -0.05, 0.02})});
  EXPECT_LT(c.measured, 0.0);
  EXPECT_GT(c.measured + 2.0 * c.error, 0.0);
  EXPECT_EQ(judge(c), Verdict::not_resolvable);
}

TEST(SpinClaim, TwoRunsCombineAsIndependent) {
  const Claim c = spin_claim({run_with_contact_values("first", {-0.05, -0.07}), run_with_contact_values("second", {-0.03, -0.01})});
  EXPECT_NEAR(c.measured, -0.04, 1e-12);
  EXPECT_NEAR(c.error, std::sqrt(0.01 * 0.01 + 0.01 * 0.01) / 2.0, 1e-12);  // each run's sd/√2 = 0.01
}

TEST(SpinClaim, AMissingFileIsNotResolvable) {
  PointOutputs p;
  p.directory = (fs::temp_directory_path() / "granule_test_spin_claim_nowhere").string();
  p.status = "finished";
  p.samples.resize(1);
  const Claim c = spin_claim({p});
  EXPECT_EQ(judge(c), Verdict::not_resolvable);
  EXPECT_NE(c.unresolvable.find("no spins.h5"), std::string::npos);
}

}  // namespace
}  // namespace granule::reproduce
