// The clearance watch (checks/clearance.hpp) per step, against a step:
//   BM_ClearanceRoof/U/T     one record of the roof of U units and T trusses (generators/roof.hpp,
//                            pinned, drivers at their peak rate), the watch fed the records of
//                            kRunRecords consecutive steps of its run in turn: the broad phase
//                            runs as often as the motion makes it (its Verlet list's skin), and
//                            the time per record includes that share
//   BM_RingStep              one generalized-α step of examples/scissor/ring.yaml (the largest
//                            scissor example), Newton included
//   BM_ClearanceRing         one record of the same ring, as BM_ClearanceRoof
//   BM_ClearanceScaling/N    N free capsules (1 m long, radius 10 mm, random in a cube that holds
//                            about 2 per m³), each record moving them by up to 30 mm, beyond half
//                            the list's skin (50 mm), so that every record runs the broad phase:
//                            its growth with the number of members, no pair excluded
//   BM_CapsuleDistance       one capsule pair's distance through fcl::distance (FCL's dispatch)
//   BM_SegmentDistance       the same pair by FCL's segment–segment kernel alone
// Counters: capsules, ns_per_capsule.

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/capsule_capsule.h>
#include <fcl/narrowphase/distance.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "deploydyn/checks/clearance.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "support/cold_roof.hpp"
#include "support/stepping_run.hpp"

namespace deploydyn {
namespace {

// At ΔT = 0, where its initial coordinates are an equilibrium (the file's +130 °C needs its
// load steps first, which SteppingRun does not take).
Model ring_model() {
  return load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/scissor/ring.yaml", parse_overrides({"thermal.dT=0"}));
}

constexpr int kRunRecords = 100;

// The records of kRunRecords consecutive steps of a run in motion (after `warm_up` steps), with
// what the watch reads: coordinates and rates.
std::vector<StepRecord> run_records(bench::SteppingRun& run, int warm_up) {
  const double h = run.model.analysis.step_s;
  for (int k = 0; k < warm_up; ++k) run.integrator->step(h, *run.system, run.state);
  std::vector<StepRecord> records;
  for (int k = 0; k < kRunRecords; ++k) {
    if (k > 0) run.integrator->step(h, *run.system, run.state);
    StepRecord r = make_step_record(*run.assembler, run.state);
    r.elements.clear();
    records.push_back(std::move(r));
  }
  return records;
}

// Times watch.record on the records in turn, again from the first after the last (a jump the
// list then takes as a motion beyond its skin); the time advances as a run's would.
void time_records(benchmark::State& state, const Model& model, std::vector<StepRecord> records) {
  ClearanceWatch watch(model);
  const double h = records.size() > 1 ? records[1].time_s - records[0].time_s : 0.0;
  // The first record finds the pairs that overlap from the start: not a typical one.
  watch.record(records[0]);
  long k = 1;
  for (auto _ : state) {
    StepRecord& r = records[static_cast<std::size_t>(k) % records.size()];
    r.time_s = records[0].time_s + static_cast<double>(k) * h;
    watch.record(r);
    ++k;
  }
  const ClearanceReport report = watch.report();
  state.counters["capsules"] = report.n_capsules;
  state.counters["ns_per_capsule"] = benchmark::Counter(static_cast<double>(report.n_capsules),
                                                        benchmark::Counter::kIsIterationInvariantRate |
                                                            benchmark::Counter::kInvert);
  state.counters["closest_m"] = report.closest.empty() ? -1.0 : report.closest.front().min_distance_m;
  state.counters["broad_phases"] = report.n_lists;
}

void BM_ClearanceRoof(benchmark::State& state) {
  Model model = bench::cold_pinned_roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (Driver& driver : model.drivers) driver.profile = TimeFunction::constant(kRoofPeakRate_rad_s);
  bench::SteppingRun run(std::move(model));
  time_records(state, run.model, run_records(run, 0));
}
BENCHMARK(BM_ClearanceRoof)
    ->Args({100, 1})
    ->Args({10'000, 1})
    ->Args({263, 10})
    ->Iterations(2 * kRunRecords)  // twice through the run's records
    ->Unit(benchmark::kMicrosecond);

void BM_RingStep(benchmark::State& state) {
  bench::SteppingRun run(ring_model());
  const double h = run.model.analysis.step_s;
  for (auto _ : state) {
    if (!run.integrator->step(h, *run.system, run.state).converged) {
      state.SkipWithError("Newton failed");
      break;
    }
  }
  state.counters["beams"] = run.model.n_beams();
}
BENCHMARK(BM_RingStep)->Unit(benchmark::kMicrosecond);

void BM_ClearanceRing(benchmark::State& state) {
  bench::SteppingRun run(ring_model());
  time_records(state, run.model, run_records(run, 20));
}
BENCHMARK(BM_ClearanceRing)->Iterations(2 * kRunRecords)->Unit(benchmark::kMicrosecond);

// N bars of their own nodes: 1 m long, random in direction and place, about 2 per m³.
Model free_capsules(int n) {
  Model model;
  model.dimension = 3;
  Material steel;
  steel.name = "steel";
  steel.youngs_modulus_Pa = 2.0e11;
  model.materials.push_back(steel);
  std::mt19937 random(7);
  const double side_m = std::cbrt(n / 2.0);
  std::uniform_real_distribution<double> place(0.0, side_m), direction(-1.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d a(place(random), place(random), place(random));
    const Eigen::Vector3d along = Eigen::Vector3d(direction(random), direction(random), direction(random)).normalized();
    Node& end_a = model.nodes.emplace_back();
    end_a.name = fmt::format("a{}", i);
    end_a.position_m = a;
    Node& end_b = model.nodes.emplace_back();
    end_b.name = fmt::format("b{}", i);
    end_b.position_m = a + along;
    BarElement bar;
    bar.name = fmt::format("{}", i);
    bar.node_a = 2 * i;
    bar.node_b = 2 * i + 1;
    bar.area_m2 = std::numbers::pi * 1e-4;  // radius 10 mm
    model.bars.push_back(bar);
  }
  return model;
}

void BM_ClearanceScaling(benchmark::State& state) {
  const Model model = free_capsules(static_cast<int>(state.range(0)));
  const DofMap dofs(model);
  std::vector<StepRecord> records(2);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> shift(-3e-2, 3e-2);
  for (std::size_t r = 0; r < 2; ++r) {
    records[r].time_s = static_cast<double>(r) * 1e-3;
    records[r].dimension = 3;
    records[r].q.resize(dofs.n_dofs());
    records[r].v = Eigen::VectorXd::Zero(dofs.n_dofs());
    for (int n = 0; n < model.n_nodes(); ++n) {
      for (int i = 0; i < 3; ++i) {
        records[r].q[dofs.index(n, i)] = model.nodes[static_cast<std::size_t>(n)].position_m[i] + (r == 0 ? 0.0 : shift(random));
      }
    }
  }
  time_records(state, model, records);
}
BENCHMARK(BM_ClearanceScaling)->Arg(100)->Arg(1'000)->Arg(10'000)->Iterations(200)->Unit(benchmark::kMicrosecond);

// Two crossing capsules 0.1 m apart, as the watch hands them to FCL.
struct CapsulePair {
  std::shared_ptr<fcl::Capsuled> shape = std::make_shared<fcl::Capsuled>(0.01, 1.0);
  fcl::CollisionObjectd a{shape}, b{shape};
  CapsulePair() {
    fcl::Transform3d across = fcl::Transform3d::Identity();
    across.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
    across.translation() = Eigen::Vector3d(0.1, 0.0, 0.0);
    b.setTransform(across);
  }
};

void BM_CapsuleDistance(benchmark::State& state) {
  const CapsulePair pair;
  double sum = 0.0;
  for (auto _ : state) {
    fcl::DistanceRequestd request;
    fcl::DistanceResultd result;
    fcl::distance(&pair.a, &pair.b, request, result);
    sum += result.min_distance;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_CapsuleDistance);

void BM_SegmentDistance(benchmark::State& state) {
  const Eigen::Vector3d p1(0, 0, -0.5), q1(0, 0, 0.5), p2(0.1, 0.5, 0), q2(0.1, -0.5, 0);
  double sum = 0.0;
  for (auto _ : state) {
    double s = 0.0, t = 0.0;
    Eigen::Vector3d c1, c2;
    sum += std::sqrt(fcl::detail::closestPtSegmentSegment(p1, q1, p2, q2, &s, &t, &c1, &c2)) - 0.02;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_SegmentDistance);

}  // namespace
}  // namespace deploydyn
