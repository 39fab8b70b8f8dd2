// The published observations file (data/experiments.csv): the shipped rows parse, each with its source and basis,
// and a bad row is refused naming its line and column.
#include <gtest/gtest.h>

#include <cmath>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/experiments.hpp"

namespace rbcstab {
namespace {

const std::string kHeader =
    "source,reference,observation,kind,viscosity_Pa_s,shear_rate_lo_per_s,shear_rate_hi_per_s,stress_Pa,precision,"
    "basis\n";

TEST(Experiments, ShippedFileParsesWithItsSources) {
  const std::string path = shipped_observations("");
  ASSERT_FALSE(path.empty());
  const auto rows = read_observations(path);
  ASSERT_GE(rows.size(), 3u);
  for (const PublishedObservation& o : rows) {
    EXPECT_FALSE(o.reference.empty()) << o.source;
    EXPECT_FALSE(o.basis.empty()) << o.source;
  }
  // Abkarian et al. 2007: swinging at a stress of the order of 0.1 Pa (their abstract).
  EXPECT_EQ(rows[0].kind, "stress");
  EXPECT_EQ(rows[0].stress, 0.1);
  EXPECT_EQ(to_json(rows).size(), rows.size());
}

TEST(Experiments, QuotedFieldsKeepTheirCommas) {
  const auto rows = parse_observations(kHeader + "a,\"b, c \"\"d\"\"\",x,point,1e-3,10,20,,range,\"e, f\"\n", "t.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].reference, "b, c \"d\"");
  EXPECT_EQ(rows[0].basis, "e, f");
  EXPECT_TRUE(std::isnan(rows[0].stress));
}

TEST(Experiments, BadRowsNameLineAndColumn) {
  auto message = [](const std::string& text) {
    try {
      parse_observations(text, "t.csv");
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "experiments");
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("source,reference\n").find("t.csv:1: the header has no column 'observation'"), std::string::npos);
  EXPECT_NE(message(kHeader + "a,b,x,point,-1e-3,10,20,,range,e\n").find("t.csv:2: column viscosity_Pa_s = '-1e-3'"),
            std::string::npos);
  EXPECT_NE(message(kHeader + "a,b,x,point,1mPa,10,20,,range,e\n").find("viscosity_Pa_s = '1mPa'"), std::string::npos);
  EXPECT_NE(message(kHeader + "a,b,x,wobble,1e-3,10,20,,range,e\n").find("kind = 'wobble'"), std::string::npos);
  EXPECT_NE(message(kHeader + "a,b,x,point,1e-3,20,10,,range,e\n").find("lo_per_s > "), std::string::npos);
  EXPECT_NE(message(kHeader + "a,b,x,stress,,,,,order,e\n").find("kind stress needs stress_Pa"), std::string::npos);
  EXPECT_NE(message(kHeader + "#c\na,b,x,stress,,,,0.1,exact,e\n").find("t.csv:3: column precision"),
            std::string::npos);
  EXPECT_NE(message(kHeader + "a,b,x,stress\n").find("4 fields"), std::string::npos);
}

}  // namespace
}  // namespace rbcstab
