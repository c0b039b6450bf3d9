// The free motions of under-supported models, grouped by part and fitted as rigid motions
// (docs/theory.md, "Diagnosis of free motions"), against axes and points known from the geometry.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <string>

#include "deploydyn/assembly/free_motion.hpp"
#include "deploydyn/assembly/mobility.hpp"
#include "deploydyn/io/model_loader.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// The fit is exact for a rigid motion; null vectors carry ~1e-10 of round-off.
constexpr double kGeometryTolerance = 1e-6;

constexpr const char* kSteel = "materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}\n";

std::string bar(const std::string& name, const std::string& a, const std::string& b) {
  return "  " + name + ": {nodes: [" + a + ", " + b + "], area: 1.0e-4, material: steel, mass: 1.0}\n";
}

struct Diagnosis {
  Model model;
  std::vector<FreeMotion> motions;
};

Diagnosis diagnose(Model model) {
  Diagnosis out{std::move(model), {}};
  const Assembler assembler(out.model);
  const Mobility m = mobility(assembler);
  out.motions = free_motions(out.model, assembler.dof_map(), assembler.initial_coordinates(), m.free_motions);
  return out;
}

Diagnosis diagnose(const std::string& yaml) { return diagnose(load_model_from_string(yaml, "model")); }

std::vector<std::string> node_names(const Model& model, const FreeMotion& motion) {
  std::vector<std::string> out;
  for (const int n : motion.nodes) out.push_back(model.nodes[n].name);
  return out;
}

// Distance from `point` to the line through `on_line` along `direction` (unit).
double distance_to_line(const Eigen::Vector3d& point, const Eigen::Vector3d& on_line, const Eigen::Vector3d& direction) {
  return (point - on_line).cross(direction).norm();
}

// The canopy (../shared/models/canopy3d.yaml) without the roller under the right girder's far
// foot: the right girder turns about z through its pinned foot (0, 0, 1.5), the joint Rfoot.
TEST(FreeMotion, CanopyWithoutASupportTurnsItsRightGirderAboutItsFoot) {
  Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/assembly/models/canopy3d.yaml");
  const auto removed = std::find_if(model.supports.begin(), model.supports.end(),
                                    [&](const FixedNode& s) { return model.nodes[s.node].name == "Rm2b_4"; });
  ASSERT_NE(removed, model.supports.end());
  model.supports.erase(removed);
  const Diagnosis d = diagnose(std::move(model));
  ASSERT_EQ(d.motions.size(), 1u);
  const FreeMotion& m = d.motions[0];
  EXPECT_EQ(m.kind, FreeMotion::Kind::rotation);
  EXPECT_NEAR(std::abs(m.direction.z()), 1.0, kGeometryTolerance);
  EXPECT_LT(distance_to_line(m.point_m, Eigen::Vector3d(0, 0, 1.5), Eigen::Vector3d::UnitZ()), kGeometryTolerance);
  const std::vector<std::string> names = node_names(d.model, m);
  EXPECT_EQ(names.size(), 30u);  // the right girder: 3 units × 2 beams × 5 nodes
  EXPECT_TRUE(std::all_of(names.begin(), names.end(), [](const std::string& n) { return n.rfind("Rm", 0) == 0; }));
  EXPECT_NE(std::find(m.pivots.begin(), m.pivots.end(), "joint Rfoot"), m.pivots.end());
  EXPECT_EQ(describe(d.model, m),
            "part with nodes Rm0a_0 … Rm2b_4 (30 nodes): free rotation about z through (0, 0, 1.5) at joint Rfoot");
}

// A four-bar of bars, crank A–B, coupler B–C, rocker C–D, without a driver: B and C move; the
// coupler alone turns rigidly, but about the instant centre where AB and DC meet, on no node:
// the links turn about A and D, a mechanism motion.
TEST(FreeMotion, UndrivenFourBarIsAMechanismMotionAtItsGroundPivots) {
  const Diagnosis d = diagnose(std::string(kSteel) +
                               "nodes: {A: [0, 0], B: [0.1, 0.3], C: [0.5, 0.4], D: [0.6, 0]}\n"
                               "elements:\n" +
                               bar("crank", "A", "B") + bar("coupler", "B", "C") + bar("rocker", "C", "D") +
                               "supports: [{node: A}, {node: D}]\n");
  ASSERT_EQ(d.motions.size(), 1u);
  const FreeMotion& m = d.motions[0];
  EXPECT_EQ(m.kind, FreeMotion::Kind::mechanism);
  EXPECT_EQ(node_names(d.model, m), (std::vector<std::string>{"B", "C"}));
  EXPECT_EQ(describe(d.model, m), "part with nodes B, C: mechanism motion (not rigid) turning at node A, node D");
}

// A planar triangle truss on two rollers that both hold y: nothing holds x.
TEST(FreeMotion, TrussWithoutItsFixedBearingTranslatesAlongX) {
  const Diagnosis d = diagnose(std::string(kSteel) +
                               "nodes: {A: [0, 0], B: [2, 0], C: [1, 1.2], E: [3, 1.2]}\n"
                               "elements:\n" +
                               bar("1", "A", "B") + bar("2", "B", "C") + bar("3", "C", "A") + bar("4", "B", "E") +
                               bar("5", "C", "E") + "supports: [{node: A, fix: [y]}, {node: B, fix: [y]}]\n");
  ASSERT_EQ(d.motions.size(), 1u);
  const FreeMotion& m = d.motions[0];
  EXPECT_EQ(m.kind, FreeMotion::Kind::translation);
  EXPECT_NEAR(std::abs(m.direction.x()), 1.0, kGeometryTolerance);
  EXPECT_EQ(describe(d.model, m), "part with nodes A, B, C, E: free translation along x");
}

// A bar tetrahedron held at A in x, y, z and at B in y, z: C's support is missing, and the
// whole turns about the line AB (closed form: the axis through A along B − A).
TEST(FreeMotion, TetrahedronMissingASupportAxisTurnsAboutTheLineThroughItsSupports) {
  const Diagnosis d = diagnose(std::string(kSteel) +
                               "nodes: {A: [0, 0, 0], B: [2, 0.5, 0], C: [0.4, 1.5, 0.1], D: [0.8, 0.6, 1.3]}\n"
                               "elements:\n" +
                               bar("AB", "A", "B") + bar("AC", "A", "C") + bar("AD", "A", "D") + bar("BC", "B", "C") +
                               bar("BD", "B", "D") + bar("CD", "C", "D") +
                               "supports: [{node: A, fix: [x, y, z]}, {node: B, fix: [y, z]}]\n");
  ASSERT_EQ(d.motions.size(), 1u);
  const FreeMotion& m = d.motions[0];
  EXPECT_EQ(m.kind, FreeMotion::Kind::rotation);
  const Eigen::Vector3d ab = Eigen::Vector3d(2, 0.5, 0).normalized();
  EXPECT_NEAR(std::abs(m.direction.dot(ab)), 1.0, kGeometryTolerance);
  EXPECT_LT(distance_to_line(m.point_m, Eigen::Vector3d::Zero(), ab), kGeometryTolerance);
  EXPECT_EQ(node_names(d.model, m), (std::vector<std::string>{"C", "D"}));
  EXPECT_NE(describe(d.model, m).find("free rotation about (0.9701, 0.2425, 0) through (0, 0, 0)"), std::string::npos)
      << describe(d.model, m);
}

// Two trusses side by side, neither held enough: the left one on two y-rollers slides along x,
// the right one, pinned at P only, turns about P. Both are named, each with its motion.
TEST(FreeMotion, TwoIndependentFreePartsAreBothNamed) {
  const Diagnosis d = diagnose(std::string(kSteel) +
                               "nodes: {A: [0, 0], B: [2, 0], C: [1, 1.2], P: [5, 0], Q: [7, 0], R: [6, 1.2]}\n"
                               "elements:\n" +
                               bar("1", "A", "B") + bar("2", "B", "C") + bar("3", "C", "A") + bar("4", "P", "Q") +
                               bar("5", "Q", "R") + bar("6", "R", "P") +
                               "supports: [{node: A, fix: [y]}, {node: B, fix: [y]}, {node: P}]\n");
  ASSERT_EQ(d.motions.size(), 2u);
  EXPECT_EQ(node_names(d.model, d.motions[0]), (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_EQ(d.motions[0].kind, FreeMotion::Kind::translation);
  EXPECT_NEAR(std::abs(d.motions[0].direction.x()), 1.0, kGeometryTolerance);
  EXPECT_EQ(node_names(d.model, d.motions[1]), (std::vector<std::string>{"Q", "R"}));  // P stays
  EXPECT_EQ(d.motions[1].kind, FreeMotion::Kind::rotation);
  EXPECT_LT((d.motions[1].point_m - Eigen::Vector3d(5, 0, 0)).norm(), kGeometryTolerance);
  EXPECT_EQ(describe(d.model, d.motions),
            "part with nodes A, B, C: free translation along x; "
            "part with nodes Q, R: free rotation about the out-of-plane axis through (5, 0)");
}

}  // namespace
}  // namespace deploydyn
