#pragma once
// Pantograph canopies of 3D beams, the family of ../shared/models/canopy3d.yaml (2 girders of 3
// units) grown to any size: `girders` translational scissor girders 1.5 m apart, each of `units`
// units of two members (four beam elements each) pinned at their central hinge and to the next
// unit at their ends, the first foot pinned to a clamped stub, the last foot on a roller; bar
// purlins join neighbouring girders at every member end; every girder's second hinge driven.
// 25 girders of 50 units are 10 025 beams, the "3D scissor dome of 10⁴ beam elements" of issue
// 30 (there is no dome generator: this is its vault).

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "deploydyn/io/model_loader.hpp"

namespace deploydyn::bench {

inline std::string scissor_canopy_yaml(int girders, int units) {
  constexpr double dx = 0.282647043574031, height = 1.6029710395900958, spacing = 1.5;
  constexpr int elements = 4;  // per member
  const auto node = [](int g, int k, char member, int i) { return fmt::format("g{}u{}{}_{}", g, k, member, i); };
  std::string nodes = "nodes:\n", members = "elements:\n", joints = "joints:\n", supports = "supports:\n",
              drivers = "drivers:\n";
  const std::string beam = "area: 0.000684, inertia_z: 3.714e-07, inertia_y: 3.714e-07, torsion: 5.6e-07, "
                           "orientation: [0, 0, 1], material: steel";
  for (int g = 0; g < girders; ++g) {
    const double z = spacing * g;
    for (int k = 0; k < units; ++k) {
      for (const char member : {'a', 'b'}) {
        for (int i = 0; i <= elements; ++i) {
          const double s = double(i) / elements;
          const double y = member == 'a' ? height * s : height * (1.0 - s);
          nodes += fmt::format("  {}: [{}, {}, {}]\n", node(g, k, member, i), dx * (k + s), y, z);
          if (i > 0) {
            members += fmt::format("  g{}u{}{}_e{}: {{type: beam, nodes: [{}, {}], {}}}\n", g, k, member, i - 1,
                                   node(g, k, member, i - 1), node(g, k, member, i), beam);
          }
          if (g > 0 && (i == 0 || i == elements)) {
            members += fmt::format("  p{}u{}{}_{}: {{nodes: [{}, {}], area: 0.0002, material: steel}}\n", g, k,
                                   member, i, node(g - 1, k, member, i), node(g, k, member, i));
          }
        }
      }
      joints += fmt::format("  g{}h{}: {{type: pin, nodes: [{}, {}], axis: [0, 0, 1]}}\n", g, k, node(g, k, 'a', 2),
                            node(g, k, 'b', 2));
      if (k > 0) {
        joints += fmt::format("  g{}in{}: {{type: pin, nodes: [{}, {}], axis: [0, 0, 1]}}\n", g, k,
                              node(g, k - 1, 'b', elements), node(g, k, 'a', 0));
        joints += fmt::format("  g{}out{}: {{type: pin, nodes: [{}, {}], axis: [0, 0, 1]}}\n", g, k,
                              node(g, k - 1, 'a', elements), node(g, k, 'b', 0));
      }
    }
    nodes += fmt::format("  g{}gnd: [-0.1, 0, {}]\n  g{}stub: [0, 0, {}]\n", g, z, g, z);
    members += fmt::format("  g{}stub: {{type: beam, nodes: [g{}gnd, g{}stub], {}}}\n", g, g, g, beam);
    joints += fmt::format("  g{}foot: {{type: pin, nodes: [g{}stub, {}], axis: [0, 0, 1]}}\n", g, g, node(g, 0, 'a', 0));
    supports += fmt::format("  - {{node: g{}gnd, fix: [x, y, z, rotation]}}\n", g);
    supports += fmt::format("  - {{node: {}, fix: [y, z]}}\n", node(g, units - 1, 'b', elements));
    drivers += fmt::format("  motor{}: {{type: revolute, joint: g{}h{}, reading: angle, profile: {{type: smooth_step, "
                           "t0: 0, v0: 0, t1: 10, v1: 1.5707963267948966}}}}\n",
                           g, g, std::min(1, units - 1));
  }
  return fmt::format("name: pantograph canopy, {} scissor girders x {} units\n", girders, units) + nodes +
         "materials:\n  steel: {E: 210000000000, alpha: 1.2e-05, density: 7850}\n" + members + joints + supports +
         drivers +
         "thermal: {dT: 0}\ngravity: [0, -9.81, 0]\nanalysis:\n  type: dynamic\n  end: 12\n  step: 0.005\n"
         "  output_interval: 0.05\n  integrator: {type: generalized_alpha, rho_inf: 0.9}\n";
}

inline Model scissor_canopy(int girders, int units) {
  return load_model_from_string(scissor_canopy_yaml(girders, units), fmt::format("canopy {}x{}", girders, units));
}

}  // namespace deploydyn::bench
