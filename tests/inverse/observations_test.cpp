// The observation file: format, units, and an error naming the file line and the column for each kind of bad data.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/inverse/observations.hpp"

namespace rbcstab {
namespace {

const std::string kHeader = "observable,shear_rate,viscosity,value,uncertainty,unit,regime,note\n";

TEST(ObservationData, ReadsRowsInCanonicalUnits) {
  const std::string text =
      "# Synthetic: a comment\n"
      "observable,shear_rate[1/s],viscosity[Pa s],value,uncertainty,unit,regime,note\n"
      "inclination_angle,100,0.001,10,1,deg,swinging,\"read off Fig. 2, a note with a comma\"\n"
      "swinging_frequency,100,0.001,100,5,rad/s,,\n"
      "transition_shear_rate,,0.002,50,5,1/s,,\n"
      "regime,20,0.001,,,,tumbling,\n";
  const ObservationData d = parse_observation_data(text, "obs.csv");
  ASSERT_EQ(d.rows.size(), 4u);
  ASSERT_EQ(d.comments.size(), 1u);
  EXPECT_EQ(d.rows[0].line, 3);
  EXPECT_NEAR(d.rows[0].value, 10 * kPi / 180, 1e-15);
  EXPECT_NEAR(d.rows[0].uncertainty, kPi / 180, 1e-15);
  EXPECT_EQ(d.rows[0].viscosity, 0.001);
  EXPECT_TRUE(d.rows[0].has_regime);
  EXPECT_EQ(d.rows[0].regime, Regime::swinging);
  EXPECT_EQ(d.rows[0].note, "read off Fig. 2, a note with a comma");
  EXPECT_NEAR(d.rows[1].value, 100 / kTwoPi, 1e-12);  // rad/s to cycles per second
  EXPECT_TRUE(std::isnan(d.rows[2].shear_rate));
  EXPECT_EQ(d.rows[2].value, 50);
  EXPECT_EQ(d.rows[3].observable, Observable::regime);
  EXPECT_EQ(d.rows[3].regime, Regime::tumbling);
}

TEST(ObservationData, ViscosityWithoutBracketIsMilliPascalSeconds) {
  const ObservationData d = parse_observation_data(kHeader + "inclination_angle,100,1.2,0.2,0.01,rad,,\n", "f");
  EXPECT_NEAR(d.rows[0].viscosity, 1.2e-3, 1e-18);
}

// The message names the file line and the column.
void expect_error(const std::string& text, const std::string& where, const std::string& column) {
  try {
    parse_observation_data(text, "obs.csv");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InvalidArgument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("obs.csv:" + where + ":"), std::string::npos) << m;
    EXPECT_NE(m.find("column '" + column + "'"), std::string::npos) << m;
  }
}

TEST(ObservationData, BadDataNamesRowAndColumn) {
  expect_error("# only comments\n", "1", "*");
  expect_error("", "1", "*");
  expect_error("# c\nobservable,shear_rate,viscosity,value,uncertainty\n", "2", "unit");
  expect_error(kHeader, "1", "*");  // a header without rows
  expect_error("observable,shear_rate[m/s],viscosity,value,uncertainty,unit\n", "1", "shear_rate[m/s]");
  expect_error("observable,shear_rate,viscosity[cP],value,uncertainty,unit\n", "1", "viscosity[cP]");
  expect_error(kHeader + "inclination_angle,100,1,10,1,deg,,\ninclination_angle,100,1,10,1,degrees,,\n", "3", "unit");
  expect_error(kHeader + "inclination_angle,100,1,10,1,Hz,,\n", "2", "unit");  // a unit of another observable
  expect_error(kHeader + "swinging_frequency,100,1,10,1,deg,,\n", "2", "unit");
  expect_error(kHeader + "inclination_angle,100,1,10,-1,deg,,\n", "2", "uncertainty");
  expect_error(kHeader + "inclination_angle,100,1,10,0,deg,,\n", "2", "uncertainty");
  expect_error(kHeader + "inclination_angle,100,1,ten,1,deg,,\n", "2", "value");
  expect_error(kHeader + "inclination_angle,fast,1,10,1,deg,,\n", "2", "shear_rate");
  expect_error(kHeader + "inclination_angle,100,-1,10,1,deg,,\n", "2", "viscosity");
  expect_error(kHeader + "regime,100,1,,,,wobbling,\n", "2", "regime");
  expect_error(kHeader + "inclination_angle,100,1,10,1,deg,undetermined,\n", "2", "regime");
  expect_error(kHeader + "regime,100,1,3,,,tumbling,\n", "2", "value");
  expect_error(kHeader + "tilt,100,1,10,1,deg,,\n", "2", "observable");
  expect_error(kHeader + "transition_shear_rate,100,1,10,1,1/s,,\n", "2", "shear_rate");
  expect_error(kHeader + "inclination_angle,,1,10,1,deg,,\n", "2", "shear_rate");
  expect_error(kHeader + "inclination_angle,100,1,10,1,deg\n", "2", "*");  // fewer fields than the header
}

}  // namespace
}  // namespace rbcstab
