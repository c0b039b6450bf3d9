// The material law of temperature tables (model/material_law.hpp; docs/theory.md,
// "Temperature-dependent material properties"): values and slopes of the piecewise-linear
// tables against hand-computed closed forms, the secant thermal strain ∫α dT against an
// independent quadrature (support/table_reference.hpp: two-point Gauss on each linear piece,
// exact), the derivatives
// against central differences, and a constant table against the plain constant.
#include "deploydyn/model/material_law.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/table_reference.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// A steel data sheet: E at 20, 100, 200, 400 °C and α at 20, 200, 400 °C.
const PropertyTable kYoungs{{20.0, 100.0, 200.0, 400.0}, {2.1e11, 2.05e11, 1.95e11, 1.7e11}};
const PropertyTable kExpansion{{20.0, 200.0, 400.0}, {1.2e-5, 1.3e-5, 1.4e-5}};
constexpr double kReference_C = 20.0;

Material steel() {
  Material m;
  m.name = "steel";
  m.youngs_modulus_Pa = 2.1e11;
  m.expansion_per_C = 1.2e-5;
  m.youngs_modulus_table_Pa = kYoungs;
  m.expansion_table_per_C = kExpansion;
  return m;
}

// α written apart from the law (support/table_reference.hpp).
const testing::ReferenceTable kReferenceExpansion{kExpansion.temperature_C, kExpansion.value};
double alpha_at(double temperature_C) { return kReferenceExpansion.at(temperature_C); }
double gauss_strain(double from_C, double to_C) { return kReferenceExpansion.integral(from_C, to_C); }

TEST(MaterialLaw, TableValuesAndSlopesMatchHandComputedOnes) {
  // E(320 °C) = 1.95e11 − 120/200 · 0.25e11 = 1.8e11, slope −0.25e11/200 per °C.
  EXPECT_NEAR(table_value(kYoungs, 320.0), 1.8e11, 1e-14 * 1.8e11);
  EXPECT_DOUBLE_EQ(table_slope(kYoungs, 320.0), -0.25e11 / 200.0);
  // At an entry, the slope of the interval above it.
  EXPECT_DOUBLE_EQ(table_value(kYoungs, 100.0), 2.05e11);
  EXPECT_DOUBLE_EQ(table_slope(kYoungs, 100.0), -0.1e11 / 100.0);
  // Held at the end values outside, with zero slope.
  EXPECT_EQ(table_value(kYoungs, -40.0), 2.1e11);
  EXPECT_EQ(table_value(kYoungs, 650.0), 1.7e11);
  EXPECT_EQ(table_slope(kYoungs, -40.0), 0.0);
  EXPECT_EQ(table_slope(kYoungs, 650.0), 0.0);
  // ∫_{20}^{320} α = 180 · 1.25e-5 + 120 · (1.3e-5 + 1.36e-5)/2 = 3.846e-3.
  EXPECT_NEAR(table_integral(kExpansion, 20.0, 320.0), 3.846e-3, 1e-15);
}

TEST(MaterialLaw, SecantStrainIsTheExactIntegralOfAlpha) {
  const Material material = steel();  // the law points into its tables
  const MaterialLaw law(material, kReference_C);
  ASSERT_TRUE(law.varies());
  // Below, inside and beyond the table, across its entries, heating and cooling.
  for (const double change_C : {-150.0, -5.0, 0.0, 37.5, 180.0, 250.0, 380.0, 600.0}) {
    SCOPED_TRACE(change_C);
    const MaterialAt m = law.at(change_C);
    const double exact = gauss_strain(kReference_C, kReference_C + change_C);
    EXPECT_NEAR(m.thermal_strain, exact, 1e-14 * std::max(1e-3, std::abs(exact)));
    EXPECT_NEAR(m.expansion_per_C, alpha_at(kReference_C + change_C), 1e-20);
  }
  EXPECT_EQ(law.at(0.0).thermal_strain, 0.0);  // stress-free at T_ref
}

// Away from the entries the law is smooth: its derivatives against central differences.
TEST(MaterialLaw, DerivativesMatchCentralDifferences) {
  const Material material = steel();  // the law points into its tables
  const MaterialLaw law(material, kReference_C);
  constexpr double kStep_C = 1e-3;
  for (const double change_C : {-60.0, 40.0, 130.0, 275.0, 500.0}) {
    SCOPED_TRACE(change_C);
    const MaterialAt m = law.at(change_C), up = law.at(change_C + kStep_C), down = law.at(change_C - kStep_C);
    EXPECT_NEAR((up.thermal_strain - down.thermal_strain) / (2.0 * kStep_C), m.expansion_per_C, 1e-9 * m.expansion_per_C);
    EXPECT_NEAR((up.youngs_modulus_Pa - down.youngs_modulus_Pa) / (2.0 * kStep_C), m.youngs_modulus_slope_Pa_C,
                1e-4 * 2.5e8 / 2.0);
    EXPECT_NEAR((up.expansion_per_C - down.expansion_per_C) / (2.0 * kStep_C), m.expansion_slope_per_C2, 1e-15);
  }
}

// A table of one value (or of equal values) is the constant: to round-off.
TEST(MaterialLaw, ConstantTableEqualsThePlainNumber) {
  Material plain;
  plain.youngs_modulus_Pa = 7.0e10;
  plain.expansion_per_C = 2.3e-5;
  Material tabled = plain;
  tabled.youngs_modulus_table_Pa = PropertyTable{{-20.0, 150.0}, {7.0e10, 7.0e10}};
  tabled.expansion_table_per_C = PropertyTable{{50.0}, {2.3e-5}};
  const MaterialLaw constant(plain, 12.0), table(tabled, 12.0);
  EXPECT_FALSE(constant.varies());
  EXPECT_TRUE(table.varies());
  for (const double change_C : {-200.0, -12.0, 0.0, 80.0, 300.0}) {
    const MaterialAt a = constant.at(change_C), b = table.at(change_C);
    EXPECT_EQ(a.youngs_modulus_Pa, b.youngs_modulus_Pa);
    EXPECT_EQ(b.youngs_modulus_slope_Pa_C, 0.0);
    EXPECT_NEAR(a.thermal_strain, b.thermal_strain, 1e-15 * std::max(1e-3, std::abs(a.thermal_strain)));
    EXPECT_EQ(a.expansion_per_C, b.expansion_per_C);
  }
}

TEST(MaterialLaw, ReferenceTemperatureComesFromTheModelTheEnvironmentOrTwentyDegrees) {
  Model model;
  EXPECT_EQ(reference_temperature_C(model), 20.0);
  model.environment = Environment{};
  model.environment->reference_temperature_K = 250.0;
  EXPECT_NEAR(reference_temperature_C(model), -23.15, 1e-12);
  model.environment.reset();
  model.reference_temperature_C = 35.0;
  EXPECT_EQ(reference_temperature_C(model), 35.0);
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
