// A fit along a flat valley (seconds: Ipopt walks the valley to the barrier's centre): mu and Delta0 enter the
// reduced motion only through S = C sqrt(15 pi/(2 Delta0)), i.e. through mu sqrt(Delta0), and kappa not at all.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/inverse/fit.hpp"
#include "synthetic_cell.hpp"

namespace rbcstab {
namespace {

TEST(FitSlow, NamesACombinationTheDataCannotSeparate) {
  const CellModel truth = synthetic_cell();
  const ObservationData data = synthetic_data(truth, 0.0, 1);
  FitOptions o;
  o.starts = 1;
  const FitResult r = fit(data, {"mu", "kappa", "Delta0"}, truth, o);
  EXPECT_EQ(r.status, FitStatus::converged) << r.message;
  ASSERT_EQ(r.estimates.size(), 3u);
  for (const FitEstimate& e : r.estimates) EXPECT_FALSE(e.identifiable) << e.parameter.name;
  ASSERT_EQ(r.unidentifiable.size(), 2u) << r.message;
  EXPECT_NE(r.message.find("no observable given depends on bending_modulus"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("ln shear_modulus +"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("Delta0 changes no prediction"), std::string::npos) << r.message;
  // What the data do measure, mu sqrt(Delta0), is recovered wherever along the valley the fit ends.
  EXPECT_NEAR(r.cell.shear_modulus * std::sqrt(r.cell.Delta0) / (truth.shear_modulus * std::sqrt(truth.Delta0)), 1.0,
              1e-4);
}

}  // namespace
}  // namespace rbcstab
