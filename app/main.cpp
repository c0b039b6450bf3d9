// deploydyn command-line tool: `run` a model into a result folder, `check` a model file, `study`
// a list of load cases (app/study_command.hpp).
// Exit codes: 0 success, 1 solver failure or interruption, 2 bad input, 3 results could not be
// written (a full disk, no permission, a result folder in use by another run).

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <new>
#include <optional>
#include <string>
#include <system_error>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/assembly/free_motion.hpp"
#include "deploydyn/assembly/mobility.hpp"
#include "deploydyn/checks/capacities_in_force.hpp"
#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/text_file.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/results/plausibility.hpp"
#include "deploydyn/solvers/initial_velocities.hpp"
#include "deploydyn/solvers/output_sampling.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/output/envelope_table.hpp"
#include "deploydyn/results/history_layout.hpp"
#include "deploydyn/runs/restart_from_folder.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "exit_codes.hpp"
#include "generate_command.hpp"
#include "modes_command.hpp"
#include "plot_command.hpp"
#include "report_command.hpp"
#include "window_command.hpp"
#include "study_command.hpp"

namespace {

using namespace deploydyn;
using namespace deploydyn::cli;


std::atomic<bool> g_stop{false};
extern "C" void request_stop(int) { g_stop.store(true); }

// "error: TEXT" on stderr, control characters escaped; never throws, even when stderr is
// closed or full (then there is no one left to tell, and the exit code says it).
void print_error(const std::string& text) noexcept {
  try {
    const std::string line = "error: " + io::printable(text) + "\n";
    std::fputs(line.c_str(), stderr);
  } catch (...) {
  }
}

// Ctrl-C, `kill` and a closed terminal all end a run (and modes, window, study) the same way:
// at the next step, with what it has written and status "interrupted".
void stop_on_signals() {
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &action, nullptr);
}


// A one-line progress display on stderr, refreshed a few times a second, for runs longer
// than about a second; silent when stderr is not a terminal or with --quiet.
class ProgressLine {
 public:
  ProgressLine(double end_time_s, bool quiet)
      : end_time_s_(end_time_s), enabled_(!quiet && isatty(fileno(stderr)) != 0),
        start_(Clock::now()), last_(start_) {}

  void update(double time_s) {
    ++steps_;
    if (!enabled_) return;
    const auto now = Clock::now();
    if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(250)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = steps_ / elapsed;
    const double eta = time_s > 0.0 ? elapsed * (end_time_s_ - time_s) / time_s : 0.0;
    fmt::print(stderr, "\r  t = {:.4g} / {:.4g} s   {:.0f} steps/s   ETA {:.0f} s   ", time_s,
               end_time_s_, rate, eta);
    shown_ = true;
  }
  void clear() {
    if (shown_) fmt::print(stderr, "\r{:60}\r", "");
  }

 private:
  using Clock = std::chrono::steady_clock;
  double end_time_s_;
  bool enabled_;
  bool shown_ = false;
  long steps_ = 0;
  Clock::time_point start_, last_;
};

// The files by which a folder shows that a run (or a study) wrote into it.
std::vector<std::string> earlier_results(const std::filesystem::path& folder, const Model& model) {
  std::vector<std::string> found;
  for (const std::string& name : {std::string(kLockFileName), std::string(kRunModelFileName),
                                  model.output.summary_file, model.output.history_file,
                                  std::string("summary.json"), std::string("study.json")}) {
    std::error_code error;
    if (std::filesystem::exists(folder / name, error) &&
        std::find(found.begin(), found.end(), name) == found.end()) {
      found.push_back(name);
    }
  }
  return found;
}

// `out_given`: --out was on the command line. Without it the run goes into ./results, but
// never over the results of an earlier run there unless `force`: they may be all that is
// left of a long run, and the user named no folder to replace.
int run_command(const std::string& model_file, const std::string& out_dir, bool out_given, bool force,
                const std::vector<std::string>& sets, bool quiet, const RestartOptions& restart) {
  const Model model = load_model(model_file, parse_overrides(sets));
  if (!out_given && !force) {
    if (const auto found = earlier_results(out_dir, model); !found.empty()) {
      print_error(fmt::format("{}/ holds the results of an earlier run ({}); give --out DIR to "
                              "write elsewhere, or --force to replace them",
                              out_dir, fmt::join(found, ", ")));
      return kExitBadInput;
    }
  }
  ProgressLine progress(model.analysis.end_time_s, quiet);
  RunControl control;
  control.progress = [&](double t) { progress.update(t); };
  control.stop = &g_stop;
  Envelope envelope;
  std::optional<Verdict> verdict;
  const RunReport report = run_to_folder(model, out_dir, control, envelope, &verdict, restart);
  progress.clear();
  for (const std::string& warning : report.warnings) fmt::print(stderr, "warning: {}\n", warning);
  // The verdict of a time history or a path; one that a check failed is said even with --quiet, as a
  // warning is.
  if (verdict && (!quiet || (!verdict->deploys && report.status == RunStatus::completed))) {
    for (const std::string& line : verdict_lines(*verdict)) fmt::print(stderr, "{}\n", line);
  }
  if (!quiet) {
    for (const std::string& note : report.notes) fmt::print(stderr, "note: {}\n", note);
  }
  if (report.status == RunStatus::completed) {
    if (!quiet) {
      // A modal analysis counts no Newton iterations of its own.
      const std::string iterations =
          report.newton_iterations == 0
              ? ""
              : fmt::format(", {} Newton iterations ({:.2f} per step)", report.newton_iterations,
                            report.steps > 0 ? double(report.newton_iterations) / report.steps : 0.0);
      fmt::print(stderr, "{}: {} in {:.3f} s{}; results in {}\n", model_file, report.message,
                 report.wall_time_s, iterations, out_dir);
    }
    return 0;
  }
  fmt::print(stderr, "{}: {}\nresults so far are in {}\n", model_file, report.message, out_dir);
  return kExitSolverFailure;
}

// A list of names for check's one screen: every name with `all`, else the first few and how many
// more there are.
std::string listed(const std::vector<std::string>& names, bool all) {
  constexpr std::size_t kShown = 8;
  if (all || names.size() <= kShown + 1) return fmt::format("{}", fmt::join(names, ", "));
  return fmt::format("{}, … and {} more (--all lists them)",
                     fmt::join(names.begin(), names.begin() + kShown, ", "), names.size() - kShown);
}

// How a dynamic run starts moving: at rest, or the model's initial_velocities with the kinetic
// energy ½ q̇ᵀ M q̇ they carry as given (the run then makes them consistent with the constraints,
// which can only take energy away: docs/theory.md, "Restart and initial velocities").
std::string initial_motion(const Model& model, const Assembler& assembler, bool list_all) {
  const InitialVelocities& given = model.initial_velocities;
  if (!given.given()) return "at rest (no initial_velocities)";
  std::vector<std::string> parts;
  const int d = model.dimension;
  const auto vector = [d](const Eigen::Vector3d& v) { return fmt::format("({:g})", fmt::join(v.head(d), ", ")); };
  if (given.spin) {
    const RigidSpin& spin = *given.spin;
    parts.push_back(d == 2 ? fmt::format("spin {:g} rad/s about z through {}", spin.rate_rad_s, vector(spin.centre_m))
                           : fmt::format("spin {:g} rad/s about {} through {}", spin.rate_rad_s,
                                         vector(spin.axis), vector(spin.centre_m)));
  }
  if (!given.nodes.empty()) {
    std::vector<std::string> nodes;
    for (const NodeVelocity& node : given.nodes) {
      nodes.push_back(fmt::format("{} {} m/s", model.nodes[node.node].name, vector(node.velocity_m_s)));
    }
    parts.push_back(fmt::format("{} node velocit{} {}", nodes.size(), nodes.size() == 1 ? "y" : "ies",
                                listed(nodes, list_all)));
  }
  const Eigen::VectorXd v = initial_velocities(model, assembler.dof_map(), assembler.initial_coordinates());
  Eigen::VectorXd mass_times_v;
  assembler.mass_times(v, mass_times_v);
  return fmt::format("{}; kinetic energy {:.6g} J as given (the run makes them consistent with the constraints)",
                     fmt::join(parts, " + "), 0.5 * v.dot(mass_times_v));
}

// Which beams bend under a through-depth temperature difference (docs/model-format.md, a beam's
// `dT_gradient_y`/`_z`; `environment.section_gradients`); "" for a model without beams.
std::string through_depth_gradients(const Model& model, bool list_all) {
  if (model.beams.empty()) return "";
  if (model.environment && model.environment->section_gradients) {
    return fmt::format("through-depth ΔT on all {} beams from the environment, each step "
                       "(environment.section_gradients)", model.beams.size());
  }
  std::vector<std::string> graded;
  double largest_C = 0.0;
  for (const BeamElement& beam : model.beams) {
    if (!beam.gradient_y_given && !beam.gradient_z_given) continue;
    graded.push_back(beam.name);
    largest_C = std::max({largest_C, std::abs(beam.temperature_gradient_y_C.value(0.0)),
                          std::abs(beam.temperature_gradient_z_C.value(0.0))});
  }
  if (graded.empty()) return "none: no beam has a through-depth ΔT (dT_gradient_y, dT_gradient_z), uniform ΔT only";
  return fmt::format("through-depth ΔT on {} of {} beams, largest |ΔT| across the depth at t = 0: {:g} °C: {}",
                     graded.size(), model.beams.size(), largest_C, listed(graded, list_all));
}

int check_command(const std::string& model_file, const std::vector<std::string>& sets, bool list_all) {
  const Model model = load_model(model_file, parse_overrides(sets));
  const Assembler assembler(model);
  int support_rows = 0;
  for (const FixedNode& s : model.supports) {
    for (int axis = 0; axis < model.dimension; ++axis) support_rows += s.axes[axis] ? 1 : 0;
    if (s.rotation) support_rows += model.dimension == 2 ? 1 : 3;
    if (s.axis) support_rows += 2;  // a hinge to ground
  }
  int joint_rows = 0;
  for (const Joint& joint : model.joints) {
    const bool keeps_axis = model.dimension == 3 && assembler.dof_map().index(joint.nodes[0], "R11") >= 0 &&
                            assembler.dof_map().index(joint.nodes[1], "R11") >= 0;
    const int frame_rows = joint.kind == Joint::Kind::ball        ? 0
                           : joint.kind == Joint::Kind::universal ? 1
                           : keeps_axis                           ? 2
                                                                  : 0;
    joint_rows += model.dimension + frame_rows;
  }
  int element_rows = 0;  // constraints the elements bring: a 3D beam node's frame RᵀR = I
  for (const ElementKind* kind : element_kinds()) {
    for (const auto& c : kind->make_constraints(model, assembler.dof_map())) element_rows += c->n_equations();
  }
  const int lock_rows = assembler.n_switched_equations();
  const int driver_rows = assembler.n_equations() - support_rows - joint_rows - element_rows - lock_rows;
  double mass = 0.0;
  for (const ElementRef& e : all_elements(model)) mass += e.kind->mass_kg(model, e.index);
  for (const Node& n : model.nodes) mass += n.point_mass_kg;
  auto names = [&](const auto& items) {
    std::vector<std::string> out;
    for (const auto& item : items) out.push_back(item.name);
    return listed(out, list_all);
  };
  // Per element type present: "3 bars: 1, 2, 3", the rigid-body conditions "3 bars", its plural.
  std::vector<std::string> element_lists, rigid_conditions, kinds_present;
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < kinds.size(); ++g) {
    const int n = kinds[g]->n_elements(model);
    if (n == 0) continue;
    const std::string plural = std::string(kinds[g]->name()) + "s";
    std::vector<std::string> element_names;
    for (int e = 0; e < n; ++e) element_names.push_back(kinds[g]->element_name(model, e));
    element_lists.push_back(fmt::format("{} {}: {}", n, plural, listed(element_names, list_all)));
    const int conditions = assembler.element_groups()[g]->n_rigid_body_conditions();
    if (conditions == 0) continue;  // hinges: no body of their own
    rigid_conditions.push_back(conditions == n ? fmt::format("{} {}", n, plural)
                                               : fmt::format("{} for {} {}", conditions, n, plural));
    kinds_present.push_back(plural);
  }
  const std::string elements_word = fmt::format("{}", fmt::join(kinds_present, " and "));
  const int free_motion = assembler.rigid_mobility() + driver_rows;  // before the drivers
  const Mobility rank = mobility(assembler);
  const auto driver_list = [&] {
    std::vector<std::string> out;
    for (const Driver& d : model.drivers) out.push_back(fmt::format("{} ({})", d.name, kDriverKinds.name(d.kind)));
    return listed(out, list_all);
  };
  const AnalysisOptions& a = model.analysis;

  fmt::print("model       {} ({})\n", model.name.empty() ? "(unnamed)" : model.name, model_file);
  fmt::print("dimension   {}D\n", model.dimension);
  fmt::print("nodes       {}: {}\n", model.n_nodes(), names(model.nodes));
  fmt::print("elements    {}; total mass {:.6g} kg\n", fmt::join(element_lists, "; "), mass);
  fmt::print("supports    {} ({} equations)\n", model.supports.size(), support_rows);
  if (!model.joints.empty()) {
    fmt::print("joints      {} ({} equations): {}\n", model.joints.size(), joint_rows, names(model.joints));
  }
  if (element_rows > 0) {
    fmt::print("frames      {} equations: the orthonormality of the 3D beam nodes' frames\n", element_rows);
  }
  if (lock_rows > 0) {
    fmt::print("locks       {} hinge locks, switched on while a hinge is {}\n", lock_rows,
               model.drivers.empty() ? "held (until released at t = 0), sticking, at a stop or latched"
                                     : "at a stop or latched (with drivers hinges start free and do not stick)");
  }
  fmt::print("drivers     {} ({} equations){}{}\n", model.drivers.size(), driver_rows,
             model.drivers.empty() ? "" : ": ", driver_list());
  fmt::print("unknowns    {} coordinates + {} multipliers\n", assembler.n_dofs(), assembler.n_equations());
  fmt::print("mobility    {} coordinates − {} support equations{}{} − {} = {} with rigid {}; "
             "{} after the drivers{}\n",
             assembler.n_dofs(), support_rows,
             joint_rows > 0 ? fmt::format(" − {} joint equations", joint_rows) : std::string(),
             element_rows > 0 ? fmt::format(" − {} frame equations", element_rows) : std::string(),
             fmt::join(rigid_conditions, " − "), free_motion, elements_word,
             free_motion - driver_rows,
             free_motion - driver_rows == 0 ? " (driven mechanism, kinematically determinate)"
             : free_motion - driver_rows > 0
                 ? " (free motion left: a dynamic run is needed)"
             : rank.by_rank && *rank.by_rank >= 0
                 ? " (by types alone; the rank below decides)"
                 : fmt::format(" (over-constrained with rigid {0}: {0} will be strained)", elements_word));
  if (rank.by_rank) {
    const int redundant = rank.n_redundant();
    const int left = *rank.by_rank;
    fmt::print("rank        {} free motions after the drivers at the initial configuration (rank of the "
               "constraint Jacobian with the {} rigid, tolerance {:g}){}\n",
               left, elements_word, kRankTolerance,
               redundant == 0 ? std::string(": the count above is exact")
                              : fmt::format(": over-constrained by {} redundant equations there (special geometry such as parallel "
                                            "or meeting axes, or more supports than needed), which the count by "
                                            "types cannot see; {}; the redundancy lets members carry self-stress, "
                                            "e.g. from a thermal strain it blocks",
                                            redundant,
                                            left == 0 ? "driven mechanism, kinematically determinate"
                                                      : "free motion left: a dynamic run is needed"));
  }
  // The free motions by name (assembly/free_motion.hpp); a part moving as a rigid body is a
  // missing support or driver far more often than an intended free flight.
  std::vector<std::string> rigid_warnings;
  if (rank.free_motions.cols() > 0) {
    const std::vector<FreeMotion> motions =
        free_motions(model, assembler.dof_map(), assembler.initial_coordinates(), rank.free_motions);
    for (const FreeMotion& motion : motions) {
      fmt::print("free        {}\n", describe(model, motion));
      const bool rigid = motion.kind == FreeMotion::Kind::translation || motion.kind == FreeMotion::Kind::rotation;
      if (rigid) rigid_warnings.push_back(describe(model, motion));
    }
    const std::vector<std::string> coordinates = moving_coordinates(assembler.dof_map(), rank.free_motions);
    fmt::print("{:<12}the coordinates that move: {}\n", "", listed(coordinates, list_all));
  } else if (assembler.n_dofs() > kMaxFreeMotionUnknowns && free_motion - driver_rows > 0) {
    fmt::print("free        not named above {} coordinates (`deploydyn run` names them if the matrix is singular)\n",
               kMaxFreeMotionUnknowns);
  }
  if (model.environment) {  // the environment sets every member's ΔT = T − T_ref
    const Environment& e = *model.environment;
    fmt::print("thermal     from the {} environment, ΔT = T − T_ref (T_ref = {:g} K): {}\n",
               kEnvironmentKinds.name(e.kind), e.reference_temperature_K,
               a.type == AnalysisType::continuation
                   ? std::string("the members' steady temperatures at t = 0, the structure as the file places it")
                   : fmt::format("every member's T by its heat balance each step, from {:g} K at t = 0",
                                 e.initial_temperature_K.value_or(e.reference_temperature_K)));
  } else {
    fmt::print("thermal     ΔT(0) = {:g} °C on {} without their own\n", model.temperature_change_C.value(0.0),
               elements_word);
  }
  if (const std::string gradients = through_depth_gradients(model, list_all); !gradients.empty()) {
    fmt::print("gradients   {}\n", gradients);
  }
  if (a.type == AnalysisType::continuation) {
    const ContinuationSettings& c = a.continuation;
    fmt::print("analysis    continuation in the {} parameter μ from {:g} to {:g}, at most {} steps, {} "
               "lowest stability eigenvalues per point (path.csv)\n",
               to_string(c.parameter), c.start, c.end, c.max_steps, c.n_eigenvalues);
  } else if (a.type == AnalysisType::modal) {
    const ModalSettings& m = a.modal;
    fmt::print("analysis    modal: the {} {} about the static equilibrium at t = {} s "
               "(modes.csv, mode shapes in vtk/)\n",
               m.n_modes,
               m.shift_rad2_s2 ? fmt::format("modes nearest ω² = {:g} rad²/s²", *m.shift_rad2_s2) : "lowest modes",
               fmt::join(m.times_s, ", "));
  } else {
    fmt::print("analysis    {}, t = 0 → {:g} s, step {:g} s ({:.0f} steps){}\n", to_string(a.type),
               a.end_time_s, a.step_s, a.end_time_s / a.step_s,
               a.adaptive.enabled && a.type == AnalysisType::dynamic
                   ? fmt::format(", adaptive (tolerance {:g} m)", a.adaptive.tolerance_m)
                   : std::string());
    if (a.type == AnalysisType::dynamic) {
      // The scheme `run` will use, whether the file gives it or not (docs/model-format.md).
      const IntegratorOptions& i = a.integrator;
      const bool trapezoidal = i.kind == IntegratorOptions::Kind::newmark && i.beta == 0.25 && i.gamma == 0.5;
      fmt::print("integrator  {}\n",
                 i.kind == IntegratorOptions::Kind::newmark
                     ? fmt::format("newmark, β = {:g}, γ = {:g}{}", i.beta, i.gamma,
                                   trapezoidal ? " (the trapezoidal rule: no numerical damping; driver "
                                                 "efforts may zigzag from step to step)"
                                               : "")
                     : fmt::format("{}, ρ∞ = {:g}", to_string(i.kind), i.rho_infinity));
      fmt::print("start       {}\n", initial_motion(model, assembler, list_all));
    }
    const HistoryLayout history(model);
    fmt::print("history     {} columns ({}{}); extremes of every quantity over every step in {}\n",
               history.columns().size(), history.selection(),
               history.selection() == "large model default" ? ": moving nodes, forces, drivers, energies" : "",
               kEnvelopeFileName);
  }
  const LinearSolverKind solver = choose_linear_solver(a.linear_solver, assembler.n_unknowns());
  fmt::print("linear      {} for {} unknowns{}\n",
             solver == LinearSolverKind::dense                   ? "dense LU"
             : solver == LinearSolverKind::klu                   ? "KLU (sparse; large systems in two domains)"
             : solver == LinearSolverKind::klu_nested_dissection ? "KLU (sparse, nested dissection)"
             : solver == LinearSolverKind::klu_two_domains       ? "KLU (sparse, two domains)"
                                                                 : "UMFPACK (sparse)",
             assembler.n_unknowns(), a.linear_solver == LinearSolverKind::automatic ? " (automatic)" : "");
  if (a.type == AnalysisType::quasi_static || a.type == AnalysisType::dynamic) {
    const std::vector<std::string> capacities = capacity_lines(model, [&](const std::vector<std::string>& items) {
      return listed(items, list_all);
    });
    for (std::size_t i = 0; i < capacities.size(); ++i) {
      fmt::print("{:<12}{}\n", i == 0 ? "members" : i == 1 ? "checks" : "", capacities[i]);
    }
  }
  for (const std::string& motion : rigid_warnings) {
    fmt::print("warning     a part moves as a rigid body ({}): a support or driver missing? A static start fails "
               "on it, a dynamic run lets it drift\n",
               motion);
  }
  if (const std::string warning = integrator_warning(model); !warning.empty()) {
    fmt::print("warning     {}\n", warning);
  }
  RunControl control;
  control.stop = &g_stop;
  if (const auto sampling = output_sampling(assembler, control)) {
    fmt::print("sampling    lowest natural frequency at the start {:.4g} Hz: {:.3g} history rows per period\n",
               sampling->lowest_frequency_Hz, sampling->samples_per_period());
    if (const std::string warning = sampling->warning(); !warning.empty()) fmt::print("warning     {}\n", warning);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Past a file-size limit (ulimit -f) a write then fails with EFBIG, and the command says so
  // and keeps what it wrote, instead of being killed mid-row.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"deploydyn: deployment dynamics of flexible deployable structures under thermal loading"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "deploydyn " DEPLOYDYN_VERSION);

  std::string model_file, out_dir = "results";
  std::vector<std::string> sets;
  bool quiet = false;

  CLI::App* run = app.add_subcommand("run", "Run a model's analysis; write history.csv and summary.json");
  run->add_option("model", model_file, "Model file (YAML or JSON)")->required();
  run->add_option("--out,-o", out_dir,
                  "Result folder (created if needed; an earlier run's results in it are replaced)")
      ->capture_default_str();
  bool force = false;
  run->add_flag("--force,-f", force,
                "Without --out: replace the results of an earlier run in ./results (else refused)");
  run->add_option("--set,-s", sets, "Override a value of the model: PATH=VALUE, e.g. thermal.dT=130 or 'supports.1.fix=[y]'");
  run->add_flag("--quiet,-q", quiet, "No progress or closing line on stderr");
  // Restart (docs/model-format.md, "Restart"; runs/restart_from_folder.hpp).
  RestartOptions restart;
  CLI::Option* restart_from =
      run->add_option("--restart-from", restart.from_folder,
                      "Start from the last state a run of this model kept in this result folder (its states.bin), "
                      "and continue it");
  double restart_at_s = 0.0;
  run->add_option("--at", restart_at_s, "With --restart-from: the kept output time (s) to start from instead")
      ->needs(restart_from);
  run->add_flag("--keep-every-state", restart.keep_every_output,
                "Keep every output time's state in states.bin (else the last only), for restarts at any of them");

  CLI::App* check = app.add_subcommand("check", "Validate a model and print a one-screen summary");
  check->add_option("model", model_file, "Model file (YAML or JSON)")->required();
  check->add_option("--set,-s", sets, "Override a value of the model: PATH=VALUE (VALUE may be a YAML flow [list] or {mapping})");
  bool list_all = false;
  check->add_flag("--all", list_all, "List every node, element, joint and driver name (else the first few of each)");

  // A light start (docs/performance.md, 2026-11-29): a run, a check or --version (answered as soon
  // as it is read) builds only run's and check's options; the other seven commands' only when the
  // first word may name them or asks for the help that lists them.
  const std::string first_word = argc > 1 ? argv[1] : "";
  const bool every_command = first_word != "run" && first_word != "check" && first_word != "--version";
  cli::GenerateArguments generate_arguments;
  cli::StudyArguments study_arguments;
  cli::ModesArguments modes_arguments;
  cli::WindowArguments window_arguments;
  cli::ReportArguments report_arguments;
  CLI::App *generate = nullptr, *study = nullptr, *modes = nullptr, *window = nullptr, *report = nullptr,
           *plot = nullptr, *animate = nullptr;
  if (every_command) {
    generate = cli::add_generate_command(app, generate_arguments);
    study = cli::add_study_command(app, study_arguments);
    modes = cli::add_modes_command(app, modes_arguments);
    window = cli::add_window_command(app, window_arguments);
    report = cli::add_report_command(app, report_arguments);
    plot = cli::add_plot_command(app);
    animate = cli::add_animate_command(app);
  }
  // Whether the command line chose that command (never one not built).
  const auto chosen = [](const CLI::App* command) { return command != nullptr && command->parsed(); };

  // CLI11 would only say "a subcommand is required"; name the word it did not know instead.
  if (const std::string first = argc > 1 ? argv[1] : "-"; first[0] != '-' && first != "run" && first != "check" &&
                                                            first != "generate" && first != "study" && first != "modes" && first != "window" &&
                                                            first != "report" && first != "plot" && first != "animate") {
    fmt::print(stderr, "error: unknown command '{}'; commands are run, check, modes, window, generate, study, report, "
                       "plot and animate (see --help)\n", first);
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }

  try {
    // Every command that computes for long stops on a signal the same way: at its next step.
    if (*run || chosen(modes) || chosen(window) || chosen(study)) stop_on_signals();
    if (run->count("--at") > 0) restart.time_s = restart_at_s;
    if (*run) return run_command(model_file, out_dir, run->count("--out") > 0, force, sets, quiet, restart);
    if (chosen(generate)) return cli::generate_command(generate_arguments);
    if (chosen(modes)) return cli::modes_command(modes_arguments, g_stop);
    if (chosen(report)) return cli::report_command(report_arguments);
    if (chosen(plot)) return cli::run_plot_script("deploydyn_plot.py", plot->remaining());
    if (chosen(animate)) return cli::run_plot_script("deploydyn_animate.py", animate->remaining());
    if (chosen(window)) return cli::window_command(window_arguments, g_stop);
    if (chosen(study)) return cli::study_command(study_arguments, g_stop);
    return check_command(model_file, sets, list_all);
  } catch (const InputError& e) {
    print_error(e.what());
    return kExitBadInput;
  } catch (const OutputError& e) {
    print_error(e.what());
    return kExitOutputFailure;
  } catch (const std::invalid_argument& e) {
    print_error(model_file + ": " + e.what());
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    // No text may be allocated now: a fixed line, naming what the command was doing.
    std::fputs(chosen(study) ? "error: out of memory while loading or running the study\n"
               : chosen(generate) ? "error: out of memory while generating the model\n"
                           : "error: out of memory while loading or solving the model\n",
               stderr);
    return kExitSolverFailure;
  } catch (const std::system_error& e) {
    // fmt::print throws this when stderr or stdout cannot be written (closed, /dev/full).
    print_error(e.what());
    return kExitOutputFailure;
  } catch (const std::exception& e) {
    print_error(e.what());
    return kExitSolverFailure;
  }
}
