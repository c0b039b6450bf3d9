// The mobility count by types and by the rank at the initial configuration (docs/theory.md,
// "Mobility: the count and the rank"), on mechanisms whose true mobility is known by hand.
#include <gtest/gtest.h>

#include <string>

#include "deploydyn/assembly/mobility.hpp"
#include "deploydyn/io/model_loader.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr const char* kHeader =
    "materials: {steel: {E: 2.0e11, density: 7850}}\n"
    "sections: {rod: {shape: circle, diameter: 0.02}}\n";

std::string beam(const std::string& name, const std::string& a, const std::string& b) {
  return "  " + name + ": {type: beam, nodes: [" + a + ", " + b + "], material: steel, section: rod}\n";
}

Mobility mobility_of(const std::string& yaml) {
  const Model model = load_model_from_string(yaml, "mechanism");
  const Assembler assembler(model);
  return mobility(assembler);
}

// RSSR: crank A–B hinged to ground about z, rocker D–C hinged about a skew axis, coupler B′–C′
// on ball joints at both ends. 4 nodes × 12 + 2 × 12 = 72 unknowns; 2 hinges × 5, 2 balls × 3,
// 6 frames × 6, 3 beams × 6: 72 − 70 = 2, the crank's turn and the coupler's idle spin about its
// own axis. Generic geometry: the count is exact.
TEST(Mobility, SpatialFourBarRSSRIsAMechanismOfTwoFreeMotions) {
  const std::string yaml = std::string(kHeader) +
                           "nodes: {A: [0, 0, 0], B: [0.3, 0, 0], B2: [0.3, 0, 0], C2: [0.9, 0.4, 0.5], "
                           "C: [0.9, 0.4, 0.5], D: [1.0, 0.0, 0.6]}\n"
                           "elements:\n" +
                           beam("crank", "A", "B") + beam("coupler", "B2", "C2") + beam("rocker", "D", "C") +
                           "supports: [{node: A, axis: [0, 0, 1]}, {node: D, axis: [1, 0.2, 0.1]}]\n"
                           "joints:\n"
                           "  s1: {type: ball, nodes: [B, B2]}\n"
                           "  s2: {type: ball, nodes: [C, C2]}\n";
  const Mobility m = mobility_of(yaml);
  EXPECT_EQ(m.by_count, 2);
  ASSERT_TRUE(m.by_rank.has_value());
  EXPECT_EQ(*m.by_rank, 2);
  EXPECT_EQ(m.n_redundant(), 0);
}

// A planar four-bar of 3D beams with four revolute joints about parallel axes (z): the count by
// types is 6·3 − 4·5 = −2, but parallel axes make 3 equations redundant: one free motion.
TEST(Mobility, PlanarFourBarOfBeamsIsNotOverConstrained) {
  const std::string yaml = std::string(kHeader) +
                           "nodes: {A: [0, 0, 0], B: [0, 0.3, 0], B2: [0, 0.3, 0], C2: [0.5, 0.4, 0], "
                           "C: [0.5, 0.4, 0], D: [0.6, 0, 0]}\n"
                           "elements:\n" +
                           beam("crank", "A", "B") + beam("coupler", "B2", "C2") + beam("rocker", "D", "C") +
                           "supports: [{node: A, axis: [0, 0, 1]}, {node: D, axis: [0, 0, 1]}]\n"
                           "joints:\n"
                           "  b: {type: pin, nodes: [B, B2], axis: [0, 0, 1]}\n"
                           "  c: {type: pin, nodes: [C, C2], axis: [0, 0, 1]}\n";
  const Mobility m = mobility_of(yaml);
  EXPECT_EQ(m.by_count, -2);
  ASSERT_TRUE(m.by_rank.has_value());
  EXPECT_EQ(*m.by_rank, 1);
  EXPECT_EQ(m.n_redundant(), 3);
}

// The same linkage with skew hinge axes is locked: no free motion, and 74 equations on 72
// unknowns leave at least 2 redundant (the rank: exactly 2, the structure's self-stresses).
TEST(Mobility, SkewHingesLockTheFourBar) {
  const std::string yaml = std::string(kHeader) +
                           "nodes: {A: [0, 0, 0], B: [0, 0.3, 0], B2: [0, 0.3, 0], C2: [0.5, 0.4, 0], "
                           "C: [0.5, 0.4, 0], D: [0.6, 0, 0]}\n"
                           "elements:\n" +
                           beam("crank", "A", "B") + beam("coupler", "B2", "C2") + beam("rocker", "D", "C") +
                           "supports: [{node: A, axis: [0, 0, 1]}, {node: D, axis: [0.3, 0.2, 1]}]\n"
                           "joints:\n"
                           "  b: {type: pin, nodes: [B, B2], axis: [0, 0.4, 1]}\n"
                           "  c: {type: pin, nodes: [C, C2], axis: [0.5, 0, 1]}\n";
  const Mobility m = mobility_of(yaml);
  EXPECT_EQ(m.by_count, -2);
  ASSERT_TRUE(m.by_rank.has_value());
  EXPECT_EQ(*m.by_rank, 0);
  EXPECT_EQ(m.n_redundant(), 2);
}

// The Cardan shaft example: the output is held by the cross (4 equations) and its bearing (5),
// the input by its driven pin: count −3; the cross's centre on both shafts' axes makes 3 of
// them redundant, and the driven shaft is determinate.
TEST(Mobility, CardanShaftIsDeterminate) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/joints/cardan_shaft.yaml");
  const Assembler assembler(model);
  const Mobility m = mobility(assembler);
  EXPECT_EQ(m.by_count, -3);
  ASSERT_TRUE(m.by_rank.has_value());
  EXPECT_EQ(*m.by_rank, 0);
  EXPECT_EQ(m.n_redundant(), 3);
}

// Above the size limit the rank is not computed.
TEST(Mobility, LargeModelsGetTheCountOnly) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/joints/cardan_shaft.yaml");
  const Assembler assembler(model);
  EXPECT_FALSE(mobility(assembler, assembler.n_dofs() - 1).by_rank.has_value());
}

}  // namespace
}  // namespace deploydyn
