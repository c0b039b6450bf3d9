#include "deploydyn/elements/hinge/hinge_group.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "deploydyn/elements/hinge/hinge_contact.hpp"
#include "deploydyn/elements/hinge/hinge_history.hpp"
#include "deploydyn/elements/hinge/hinge_lock.hpp"
#include "deploydyn/elements/hinge/hinge_quantities.hpp"
#include "deploydyn/elements/hinge/hinge_tangent.hpp"
#include "deploydyn/elements/switching_group.hpp"

namespace deploydyn {
namespace {

using namespace hinge::history;

double sign_of(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

// Whether θ went from θ0 to θ1 through `angle` (or ended on it).
bool crossed(double angle0, double angle1, double angle) { return (angle0 - angle) * (angle1 - angle) <= 0.0 && angle0 != angle; }

// docs/theory.md, "Compliant stops and latches": the steps of a contact's first
// kResolvedDurations durations are at most 1/kStepsPerContact of it; the least impact rate ω0
// that the Hunt–Crossley law divides by (rad/s).
constexpr double kStepsPerContact = 40.0;
constexpr double kResolvedDurations = 2.0;
constexpr double kLeastImpactRate = 1e-6;
// A step that begins a contact lands where it began (the step again, as long as that) unless
// its free part is shorter than this share of a contact step.
constexpr double kLandingShare = 0.1;

// A compliant stop or latch of a hinge: penetration δ = direction (θ − angle).
struct ContactSite {
  const HingeContact* law = nullptr;
  double angle_rad = 0.0;
  double direction = 1.0;  // +1: resists θ growing past it; −1: θ falling
  bool latch = false;
};

// The contact torques of one hinge on θ (resisting θ growing, as T in f = T ∂θ/∂q).
struct ContactTorques {
  double total = 0.0;
  double elastic = 0.0;            // the k δ parts: an internal force with energy ½ k δ²
  double elastic_per_angle = 0.0;  // ∂(elastic)/∂θ
  double per_angle = 0.0;          // ∂(total)/∂θ
  double per_rate = 0.0;           // ∂(total)/∂θ̇
  double latch_Nm = 0.0, stop_Nm = 0.0;  // the moments on the latch and on the stops (≥ 0)
};

// Torques of one hinge on θ at one configuration, resisting θ growing (as f = T ∂θ/∂q).
struct HingeTorques {
  double spring = 0.0;    // k (θ − θ_r)
  double damper = 0.0;    // c θ̇
  double friction = 0.0;  // s μ r |N| while sliding
};

class HingeGroup final : public ElementGroup, public SwitchingGroup {
 public:
  // `driven`: the model has drivers, whose prescribed motion a held or sticking hinge would
  // make redundant. Then hinges start free and friction slides without sticking; without
  // drivers (a spring-driven deployment) hinges start held, and friction sticks and slips.
  HingeGroup(std::vector<HingeRecord> records, std::vector<std::string> labels, bool driven)
      : records_(std::move(records)), labels_(std::move(labels)), driven_(driven), lock_index_(records_.size(), -1) {
    int n_locks = 0;
    for (std::size_t i = 0; i < records_.size(); ++i) {
      if (records_[i].element->has_lock()) lock_index_[i] = n_locks++;
    }
    sites_.resize(records_.size());
    kinematics_.resize(records_.size());
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const HingeElement& e = *records_[i].element;
      if (e.stop_contact.compliant()) {
        if (e.stop_min_rad) sites_[i].push_back({&e.stop_contact, *e.stop_min_rad, -1.0, false});
        if (e.stop_max_rad) sites_[i].push_back({&e.stop_contact, *e.stop_max_rad, 1.0, false});
      }
      if (e.latch_rad && e.latch_contact.compliant()) {
        sites_[i].push_back({&e.latch_contact, *e.latch_rad, *e.latch_rad > e.initial_angle_rad ? 1.0 : -1.0, true});
      }
    }
  }

  int n_elements() const override { return static_cast<int>(records_.size()); }
  int n_rigid_body_conditions() const override { return 0; }

  void add_internal_force(const EvaluationPoint& at, Eigen::VectorXd& f) const override {
    KinematicsLease lease(*this);
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const HingeRecord& r = records_[i];
      if (r.element->stiffness_Nm_per_rad == 0.0 && sites_[i].empty()) continue;
      const HingeKinematics& k = lease.at(i, r.gather(at.q), false);
      double torque = spring_torque(r, k.angle_rad);
      if (!sites_[i].empty()) torque += contact_torques(i, history_of(at.history, static_cast<int>(i)), k.angle_rad, 0.0).elastic;
      scatter(r, torque * k.gradient, f);
    }
  }
  // A hinge has no thermal strain (its pin force does, through its bar: friction, a rate force).
  void add_thermal_force_derivative(const EvaluationPoint&, Eigen::VectorXd&) const override {}
  void add_thermal_force_rate(const EvaluationPoint&, Eigen::VectorXd&) const override {}
  void add_mass_times(const Eigen::VectorXd&, Eigen::VectorXd&) const override {}
  void add_weight(const Eigen::Vector3d&, Eigen::VectorXd&) const override {}

  double strain_energy(const EvaluationPoint& at) const override {
    double energy = 0.0;
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const HingeRecord& r = records_[i];
      const double k = r.element->stiffness_Nm_per_rad;
      if (k == 0.0 && sites_[i].empty()) continue;
      const double angle = r.angle_and_gradient(r.gather(at.q)).angle_rad;
      const double twist = angle - r.element->rest_angle_rad;
      if (k != 0.0) energy += 0.5 * k * twist * twist;
      for (const ContactSite& s : sites_[i]) {  // ½ k δ² of an engaged contact
        const double penetration = s.direction * (angle - s.angle_rad);
        if (penetration > 0.0 || two_sided(s, history_of(at.history, static_cast<int>(i)))) {
          energy += 0.5 * s.law->stiffness_Nm_per_rad * penetration * penetration;
        }
      }
    }
    return energy;
  }
  double largest_stiffness_diagonal(const EvaluationPoint& at) const override {
    double largest = 0.0;
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const HingeRecord& r = records_[i];
      const HingeKinematics k = r.angle_and_gradient(r.gather(at.q));
      double stiffness = r.element->stiffness_Nm_per_rad;
      if (!sites_[i].empty()) {
        stiffness += contact_torques(i, history_of(at.history, static_cast<int>(i)), k.angle_rad, 0.0).elastic_per_angle;
      }
      largest = std::max(largest, stiffness * k.gradient.cwiseAbs2().maxCoeff());
    }
    return largest;
  }
  double largest_relative_change(const Eigen::VectorXd&, const Eigen::VectorXd&) const override { return 0.0; }

  int n_matrix_entries() const override {
    int n = 0;
    for (const HingeRecord& r : records_) n += r.n_dofs() * r.n_dofs();
    return n;
  }
  void append_matrix_entries(std::vector<MatrixEntry>& entries) const override {
    for (const HingeRecord& r : records_) {
      for (const int col : r.dofs) {
        for (const int row : r.dofs) entries.push_back({row, col});
      }
    }
  }
  // c_K (K_spring + ∂f_d/∂q) + c_D ∂f_d/∂q̇ with (docs/theory.md, "Hinges")
  //   K_spring = k (∇θ ∇θᵀ + (θ − θ_r) ∇²θ)
  //   damper   f = c θ̇ ∇θ:       ∂f/∂q = c (∇θ (∇²θ q̇)ᵀ + θ̇ ∇²θ),  ∂f/∂q̇ = c ∇θ ∇θᵀ
  //   friction f = s μ r |N| ∇θ:  ∂f/∂q = s μ r (∇θ ∇|N|ᵀ + |N| ∇²θ)
  void add_iteration_matrix(const EvaluationPoint& at, const TangentWeights& w, std::span<double> values,
                            const int*& slot) const override {
    KinematicsLease lease(*this);
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const HingeRecord& r = records_[i];
      const HingeElement& e = *r.element;
      const int n = r.n_dofs();
      const HingeVector q_local = r.gather(at.q);
      const HingeKinematics& k = lease.at(i, q_local, true);
      // The factors of ∇θ∇θᵀ, ∇²θ and ∇θ (∇²θ q̇)ᵀ of each term (hinge_tangent.hpp).
      HingeTangent t;
      if (e.stiffness_Nm_per_rad != 0.0) {
        t.gradient += w.stiffness * e.stiffness_Nm_per_rad;
        t.hessian += w.stiffness * e.stiffness_Nm_per_rad * (k.angle_rad - e.rest_angle_rad);
      }
      if (at.rates != nullptr) t.rates = r.gather(*at.rates);
      if (!sites_[i].empty()) {  // T(θ, θ̇) ∇θ: ∂T/∂θ ∇θ∇θᵀ + T ∇²θ + ∂T/∂θ̇ (∇θ (∇²θ q̇)ᵀ, ∇θ∇θᵀ)
        const std::span<const double> h = history_of(at.history, static_cast<int>(i));
        if (at.rates == nullptr) {
          const ContactTorques c = contact_torques(i, h, k.angle_rad, 0.0);
          t.gradient += w.stiffness * c.elastic_per_angle;
          t.hessian += w.stiffness * c.elastic;
        } else {
          const ContactTorques c = contact_torques(i, h, k.angle_rad, k.gradient.dot(t.rates));
          t.gradient += w.stiffness * c.per_angle + w.damping * c.per_rate;
          t.hessian += w.stiffness * c.total;
          t.hessian_rates += w.stiffness * c.per_rate;
        }
      }
      if (at.rates != nullptr && e.damping_Nms_per_rad != 0.0) {
        t.gradient += w.damping * e.damping_Nms_per_rad;
        t.hessian += w.stiffness * e.damping_Nms_per_rad * k.gradient.dot(t.rates);
        t.hessian_rates += w.stiffness * e.damping_Nms_per_rad;
      }
      if (at.rates != nullptr && sliding(i, at)) {
        const PinForce p = r.pin_force(q_local, at.t);
        const double scale = w.stiffness * hinge_state(at.history, i).slip * e.friction_coefficient * e.pin_radius_m;
        t.hessian += scale * p.magnitude_N;
        t.pin = scale * p.gradient;
      }
      add_hinge_tangent(t, k, n, values, slot);
    }
  }

  bool has_rate_forces() const override {
    return std::any_of(records_.begin(), records_.end(), [](const HingeRecord& r) {
      return r.element->damping_Nms_per_rad > 0.0 || r.element->friction_coefficient > 0.0 || r.element->compliant();
    });
  }
  void add_rate_force(const EvaluationPoint& at, Eigen::VectorXd& f) const override {
    KinematicsLease lease(*this);
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const HingeRecord& r = records_[i];
      const bool slides = sliding(i, at);
      if (r.element->damping_Nms_per_rad == 0.0 && !slides && sites_[i].empty()) continue;
      const HingeVector q_local = r.gather(at.q);
      const HingeKinematics& k = lease.at(i, q_local, false);
      const double slip = slides ? hinge_state(at.history, i).slip : 0.0;
      const HingeVector rates = r.gather(*at.rates);
      const HingeTorques torques = rate_torques(r, k, q_local, rates, at.t, slip);
      double torque = torques.damper + torques.friction;
      if (!sites_[i].empty()) {  // the contacts' damping: what is not k δ
        const ContactTorques c =
            contact_torques(i, history_of(at.history, static_cast<int>(i)), k.angle_rad, k.gradient.dot(rates));
        torque += c.total - c.elastic;
      }
      scatter(r, torque * k.gradient, f);
    }
  }

  // angle, then the torques on θ in its opening direction (ElementKind::quantities).
  void results(int element, const EvaluationPoint& at, std::span<double> out) const override {
    const HingeRecord& r = records_[static_cast<std::size_t>(element)];
    const std::span<const double> h = history_of(at.history, element);
    const HingeVector q_local = r.gather(at.q);
    const HingeKinematics k = r.angle_and_gradient(q_local);
    const auto mode = h.empty() ? HingeMode::free : static_cast<HingeMode>(static_cast<int>(h[kMode]));
    const double slip = h.empty() || mode != HingeMode::free || r.element->friction_coefficient == 0.0 ? 0.0 : h[kSlip];
    const HingeVector rates = at.rates != nullptr ? r.gather(*at.rates) : HingeVector::Zero(r.n_dofs());
    HingeTorques torques = rate_torques(r, k, q_local, rates, at.t, slip);
    torques.spring = spring_torque(r, k.angle_rad);
    double lock = h.empty() ? 0.0 : h[kLockTorque];
    ContactTorques contact;
    if (!sites_[static_cast<std::size_t>(element)].empty()) {
      contact = contact_torques(static_cast<std::size_t>(element), h, k.angle_rad, k.gradient.dot(rates));
      lock += contact.total;
    }
    out[hinge::kAngle] = k.angle_rad;
    out[hinge::kTorque] = -(torques.spring + torques.damper + torques.friction + lock);
    out[hinge::kSpringTorque] = -torques.spring;
    out[hinge::kDamperTorque] = -torques.damper;
    out[hinge::kFrictionTorque] = -torques.friction;
    out[hinge::kLockTorque] = -lock;
    out[hinge::kPinForce] = r.pin_force(q_local, at.t).magnitude_N;
    out[hinge::kDissipated] = h.empty() ? 0.0 : h[kDissipated];
    out[hinge::kState] = static_cast<double>(mode);
    const double rigid = h.empty() ? 0.0 : std::abs(h[kLockTorque]);
    out[hinge::kLatchLoad] = mode == HingeMode::latched ? rigid : contact.latch_Nm;
    out[hinge::kStopLoad] = mode == HingeMode::stop_min || mode == HingeMode::stop_max ? rigid : contact.stop_Nm;
  }
  double reference_length_m(int element) const override {
    return records_[static_cast<std::size_t>(element)].reference_length_m;
  }

  // One per hinge with a latch, stops or friction, in the order of lock_index_.
  std::vector<std::unique_ptr<SwitchedConstraint>> make_switched_constraints() const override {
    std::vector<std::unique_ptr<SwitchedConstraint>> locks;
    for (std::size_t i = 0; i < records_.size(); ++i) {
      if (lock_index_[i] >= 0) locks.push_back(std::make_unique<HingeLock>(records_[i], static_cast<int>(i), labels_[i]));
    }
    return locks;
  }

  int n_history() const override { return kHistorySlots * n_elements(); }
  void initial_history(std::span<double> history) const override {
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const std::span<double> h = history.subspan(i * kHistorySlots, kHistorySlots);
      std::fill(h.begin(), h.end(), 0.0);
      h[kMode] = initial_mode(records_[i]);
      h[kLockAngle] = records_[i].element->initial_angle_rad;
      h[kLatchedAt] = -1.0;
      h[kContactSince] = -1.0;
    }
  }
  StepVerdict end_step(const StepEnds& ends, std::span<const double> before, std::span<double> after,
                       std::vector<ElementEvent>& events) const override {
    std::copy(before.begin(), before.end(), after.begin());
    KinematicsLease lease(*this);  // θ at the step's two ends, shared by the three below
    // First the switches: a latch or stop reached, a sliding hinge come to rest, a lock that
    // lets go. Any of them: the step again with the new modes, nothing else written.
    bool switched = false;
    for (std::size_t i = 0; i < records_.size() && ends.may_switch; ++i) {
      switched |= switch_mode(lease, i, ends, before.subspan(i * kHistorySlots, kHistorySlots),
                              after.subspan(i * kHistorySlots, kHistorySlots), events);
    }
    if (switched) return StepVerdict::redo;
    for (std::size_t i = 0; i < records_.size(); ++i) {
      accumulate(lease, i, ends, before.subspan(i * kHistorySlots, kHistorySlots),
                 after.subspan(i * kHistorySlots, kHistorySlots));
      if (!sites_[i].empty()) {
        track_contacts(lease, i, ends, before.subspan(i * kHistorySlots, kHistorySlots),
                       after.subspan(i * kHistorySlots, kHistorySlots), events);
      }
    }
    return StepVerdict::accept;
  }

  // docs/theory.md, "Compliant stops and latches": a step in which a contact began is taken
  // again to land where it began, or as long as a contact step; a contact's steps are at most
  // its estimated duration / kStepsPerContact while it is resolved.
  StepLimit step_limit(const StepEnds& ends, std::span<const double> before,
                       std::span<const double> after) const override {
    StepLimit limit;
    const double h = ends.time_after_s - ends.time_before_s;
    for (std::size_t i = 0; i < records_.size(); ++i) {
      if (sites_[i].empty()) continue;
      const std::span<const double> b = before.subspan(i * kHistorySlots, kHistorySlots);
      const std::span<const double> a = after.subspan(i * kHistorySlots, kHistorySlots);
      if (!(a[kContactDuration] > 0.0)) continue;  // no contact yet
      const double contact_step = a[kContactDuration] / kStepsPerContact;
      if (a[kContactSince] >= 0.0) limit.next_s = std::min(limit.next_s, contact_step);
      // Resolved in this step: a contact under way at its start, or one that began in it.
      const double began = a[kContactSince] >= 0.0 ? a[kContactSince] : b[kContactSince];
      if (began < 0.0 && b[kContactSince] < 0.0) continue;
      const double free_part = std::max(0.0, std::min(began, ends.time_after_s) - ends.time_before_s);
      if (h - free_part <= contact_step * (1.0 + 1e-9)) continue;
      limit.retry_s = std::min(limit.retry_s, free_part > kLandingShare * contact_step ? free_part : contact_step);
    }
    return limit;
  }

  int n_latches() const override {
    return static_cast<int>(std::count_if(records_.begin(), records_.end(),
                                          [](const HingeRecord& r) { return r.element->latch_rad.has_value(); }));
  }
  int n_latched(std::span<const double> history) const override {
    int n = 0;
    for (std::size_t i = 0; i < records_.size() && !history.empty(); ++i) {
      n += static_cast<HingeMode>(static_cast<int>(history[i * kHistorySlots + kMode])) == HingeMode::latched ||
           history[i * kHistorySlots + kLatchImpactOver] != 0.0;
    }
    return n;
  }


 private:
  // θ, ∇θ (∇²θ once asked for) of each hinge at its last two configurations. The residual's
  // internal and rate forces, the iteration matrix at the same q, the step's end (q before and
  // after, in three places) and the energy balance's rate force each evaluated them afresh:
  // 5.1–5.3 × the bars' cost per step (docs/performance.md, "Hinges and cables at scale").
  // A memo of a pure function of the hinge's q (compared bit for bit), so results are the same
  // bit for bit. One thread at a time: a call that finds it taken (records are built on the
  // writer thread, the residual's internal forces on a helper thread) evaluates without it.
  struct CachedKinematics {
    HingeVector q;
    HingeKinematics k;
    bool valid = false;
    bool with_hessian = false;
  };
  // And θ at the last accepted step's end, which the next step's end asks for as its start:
  // by then the Newton iterates had evicted it, one θ, ∇θ a hinge and step evaluated again.
  struct KinematicsSlots {
    std::array<CachedKinematics, 2> entries;
    int newest = 0;
    HingeVector end_q;
    double end_angle_rad = 0.0;
    bool end_valid = false;
  };
  class KinematicsLease {
   public:
    explicit KinematicsLease(const HingeGroup& group)
        : group_(group), owned_(!group.kinematics_in_use_.test_and_set(std::memory_order_acquire)) {}
    ~KinematicsLease() {
      if (owned_) group_.kinematics_in_use_.clear(std::memory_order_release);
    }
    KinematicsLease(const KinematicsLease&) = delete;
    KinematicsLease& operator=(const KinematicsLease&) = delete;
    // Hinge i's θ, ∇θ at its local q, with ∇²θ when `hessian`; valid until the next call but
    // one (no copy: a copy of ∇²θ cost as much as the memo saved).
    const HingeKinematics& at(std::size_t i, const HingeVector& q, bool hessian) {
      const HingeRecord& r = group_.records_[i];
      if (!owned_) {
        scratch_index_ = 1 - scratch_index_;
        return scratch_[scratch_index_] = hessian ? r.kinematics(q) : r.angle_and_gradient(q);
      }
      KinematicsSlots& slots = group_.kinematics_[i];
      for (int e = 0; e < 2; ++e) {
        CachedKinematics& c = slots.entries[static_cast<std::size_t>(e)];
        if (!c.valid || !same_bits(c.q, q)) continue;
        if (hessian && !c.with_hessian) {
          r.angle_hessian(q, c.k.hessian);
          c.with_hessian = true;
        }
        slots.newest = e;
        return c.k;
      }
      slots.newest = 1 - slots.newest;  // the older entry makes room
      CachedKinematics& c = slots.entries[static_cast<std::size_t>(slots.newest)];
      c.q = q;
      r.angle_and_gradient(q, c.k);  // in place: no copy of ∇²θ
      if (hessian) {
        r.angle_hessian(q, c.k.hessian);
      } else {
        c.k.hessian.resize(0, 0);  // as angle_and_gradient leaves it: not asked for
      }
      c.valid = true;
      c.with_hessian = hessian;
      return c.k;
    }

    // θ alone at q: the last step's end, an entry's, or evaluated without evicting either entry.
    double angle(std::size_t i, const HingeVector& q) const {
      const HingeRecord& r = group_.records_[i];
      if (!owned_) return r.angle(q);
      const KinematicsSlots& slots = group_.kinematics_[i];
      if (slots.end_valid && same_bits(slots.end_q, q)) return slots.end_angle_rad;
      for (const CachedKinematics& c : slots.entries) {
        if (c.valid && same_bits(c.q, q)) return c.k.angle_rad;
      }
      return r.angle(q);
    }
    // θ at an accepted step's end, for the next step's end.
    void remember_step_end(std::size_t i, const HingeVector& q, double angle_rad) {
      if (!owned_) return;
      KinematicsSlots& slots = group_.kinematics_[i];
      slots.end_q = q;
      slots.end_angle_rad = angle_rad;
      slots.end_valid = true;
    }

   private:
    static bool same_bits(const HingeVector& a, const HingeVector& b) {
      if (a.size() != b.size()) return false;
      for (Eigen::Index j = 0; j < a.size(); ++j) {
        if (std::bit_cast<std::uint64_t>(a[j]) != std::bit_cast<std::uint64_t>(b[j])) return false;
      }
      return true;
    }

    const HingeGroup& group_;
    bool owned_;
    HingeKinematics scratch_[2];  // without the memo
    std::size_t scratch_index_ = 0;
  };

  // Without drivers a hinge starts held, or sticking when it has friction (static friction
  // holds it until its torque exceeds μ r |N|); with drivers, free.
  int initial_mode(const HingeRecord& r) const {
    if (driven_ || !r.element->has_lock()) return static_cast<int>(HingeMode::free);
    return static_cast<int>(r.element->friction_coefficient > 0.0 ? HingeMode::stuck : HingeMode::held);
  }
  static double spring_torque(const HingeRecord& r, double angle) {
    return r.element->stiffness_Nm_per_rad * (angle - r.element->rest_angle_rad);
  }
  static HingeTorques rate_torques(const HingeRecord& r, const HingeKinematics& k, const HingeVector& q_local,
                                   const HingeVector& rates, double t, double slip) {
    HingeTorques torques;
    torques.damper = r.element->damping_Nms_per_rad * k.gradient.dot(rates);
    if (slip != 0.0) {
      torques.friction = slip * r.element->friction_coefficient * r.element->pin_radius_m *
                         r.pin_force(q_local, t).magnitude_N;
    }
    return torques;
  }
  // Whether hinge i slides with friction at `at` (in the step under way).
  bool sliding(std::size_t i, const EvaluationPoint& at) const {
    if (records_[i].element->friction_coefficient == 0.0) return false;
    const HingeState s = hinge_state(at.history, i);
    return s.mode == HingeMode::free && s.slip != 0.0;
  }
  std::span<const double> history_of(std::span<const double> history, int element) const {
    if (history.empty()) return {};
    return history.subspan(static_cast<std::size_t>(element) * kHistorySlots, kHistorySlots);
  }
  static void scatter(const HingeRecord& r, const HingeVector& local, Eigen::VectorXd& f) {
    for (int i = 0; i < r.n_dofs(); ++i) f[r.dofs[static_cast<std::size_t>(i)]] += local[i];
  }
  double lock_torque(std::size_t i, HingeMode mode, const StepEnds& ends) const {
    return mode == HingeMode::free || lock_index_[i] < 0 ? 0.0
                                                         : ends.switched_multipliers[static_cast<std::size_t>(lock_index_[i])];
  }

  // A latch whose catch has engaged acts both ways (docs/theory.md, "Compliant stops and latches").
  static bool two_sided(const ContactSite& s, std::span<const double> h) {
    return s.latch && !h.empty() && h[kLatchedAt] >= 0.0;
  }
  static double impact_rate(std::span<const double> h) {
    return std::max(h.empty() ? 0.0 : h[kImpactRate], kLeastImpactRate);
  }
  // Eqs. (H1), (H3) of docs/theory.md for every compliant stop and latch of hinge i at θ, θ̇.
  ContactTorques contact_torques(std::size_t i, std::span<const double> h, double angle, double rate) const {
    ContactTorques c;
    for (const ContactSite& s : sites_[i]) {
      const bool both_ways = two_sided(s, h);
      const double penetration = s.direction * (angle - s.angle_rad);
      const ContactMoment m = contact_moment(*s.law, penetration, s.direction * rate, impact_rate(h), both_ways);
      c.total += s.direction * m.moment_Nm;
      c.elastic += s.direction * m.elastic_Nm;
      if (both_ways || penetration > 0.0) c.elastic_per_angle += s.law->stiffness_Nm_per_rad;
      c.per_angle += m.per_penetration;
      c.per_rate += m.per_rate;
      (s.latch ? c.latch_Nm : c.stop_Nm) += std::abs(m.moment_Nm);
    }
    return c;
  }

  // After an accepted step of hinge i: when a contact began (and a compliant latch caught), its
  // impact rate, its duration estimated from the step, and whether it is still resolved.
  // The duration from the step's impulse: I = ∫M dt / |Δδ̇| (trapezoid), π √(I/k).
  void track_contacts(KinematicsLease& lease, std::size_t i, const StepEnds& ends, std::span<const double> before, std::span<double> after,
                      std::vector<ElementEvent>& events) const {
    const HingeRecord& r = records_[i];
    const HingeKinematics& k0 = lease.at(i, r.gather(ends.q_before), false);
    const HingeKinematics& k1 = lease.at(i, r.gather(ends.q_after), false);
    const double rate0 = k0.gradient.dot(r.gather(ends.v_before)), rate1 = k1.gradient.dot(r.gather(ends.v_after));
    const double t0 = ends.time_before_s, t1 = ends.time_after_s;
    bool touching = false;
    for (const ContactSite& s : sites_[i]) {
      const bool both_ways = two_sided(s, before);
      const double depth0 = s.direction * (k0.angle_rad - s.angle_rad), depth1 = s.direction * (k1.angle_rad - s.angle_rad);
      if (!both_ways && depth0 <= 0.0 && depth1 <= 0.0) continue;
      touching = touching || both_ways || depth1 > 0.0;
      const bool begins = !both_ways && depth0 <= 0.0;
      const double share = begins ? depth0 / (depth0 - depth1) : 0.0;  // of the step before it began
      if (begins) after[kContactSince] = t0 + share * (t1 - t0);
      const double moment0 =
          begins ? 0.0 : contact_moment(*s.law, depth0, s.direction * rate0, impact_rate(before), both_ways).moment_Nm;
      const double moment1 = contact_moment(*s.law, depth1, s.direction * rate1, impact_rate(before), both_ways).moment_Nm;
      const double impulse = 0.5 * (moment0 + moment1) * (1.0 - share) * (t1 - t0);
      const double slowed = s.direction * (rate0 - rate1);
      if (impulse > 0.0 && slowed > 0.0) {
        after[kContactDuration] = std::numbers::pi * std::sqrt(impulse / slowed / s.law->stiffness_Nm_per_rad);
      }
      if (s.latch && before[kLatchedAt] < 0.0 && depth1 > 0.0) {  // the catch engages
        after[kLatchedAt] = t1;
        events.push_back({t1, static_cast<int>(i), ElementEventKind::latched, s.angle_rad});
      }
      if (!both_ways && depth1 <= 0.0) after[kContactSince] = -1.0;  // it let go
    }
    const double since = after[kContactSince];
    if (since >= 0.0 && after[kContactDuration] > 0.0 && t1 - since >= kResolvedDurations * after[kContactDuration]) {
      after[kContactSince] = -1.0;  // resolved: its steps are free again
      if (after[kLatchedAt] >= 0.0) after[kLatchImpactOver] = 1.0;
    }
    if (!touching) after[kImpactRate] = std::abs(rate1);  // ω0 of the next contact, if it begins now
  }

  // The switch of hinge i at the end of a step, if any, into `after` and `events`.
  bool switch_mode(KinematicsLease& lease, std::size_t i, const StepEnds& ends, std::span<const double> before,
                   std::span<double> after, std::vector<ElementEvent>& events) const {
    const HingeRecord& r = records_[i];
    const HingeElement& e = *r.element;
    const auto mode = static_cast<HingeMode>(static_cast<int>(before[kMode]));
    const double t = ends.time_after_s;
    const auto to = [&](HingeMode next, double lock_angle, ElementEventKind what, double value) {
      after[kMode] = static_cast<double>(next);
      after[kLockAngle] = lock_angle;
      events.push_back({t, static_cast<int>(i), what, value});
      return true;
    };
    const HingeVector q1 = r.gather(ends.q_after), q0 = r.gather(ends.q_before);
    const double angle1 = lease.angle(i, q1), angle0 = lease.angle(i, q0);
    const double lock = lock_torque(i, mode, ends);
    switch (mode) {
      case HingeMode::free: {
        if (e.rigid_latch() && crossed(angle0, angle1, *e.latch_rad)) {
          after[kLatchedAt] = t;
          return to(HingeMode::latched, *e.latch_rad, ElementEventKind::latched, *e.latch_rad);
        }
        if (e.rigid_stops() && e.stop_min_rad && angle1 < *e.stop_min_rad) return to(HingeMode::stop_min, *e.stop_min_rad, ElementEventKind::stop, *e.stop_min_rad);
        if (e.rigid_stops() && e.stop_max_rad && angle1 > *e.stop_max_rad) return to(HingeMode::stop_max, *e.stop_max_rad, ElementEventKind::stop, *e.stop_max_rad);
        const double slip = before[kSlip];
        // Once per step: a hinge that broke loose in this step slides to its end (measured on a
        // falling chain of 100 hinged bars: without it, hinges went back and forth between
        // sticking and slipping up to the 8 redos of nearly every step, 20 Newton iterations).
        if (e.friction_coefficient > 0.0 && slip != 0.0 && !driven_ && before[kFrictionSwitched] == 0.0) {
          const double rate0 = lease.at(i, q0, false).gradient.dot(r.gather(ends.v_before));
          const double rate1 = lease.at(i, q1, false).gradient.dot(r.gather(ends.v_after));
          if (rate1 * slip < 0.0) {  // came to rest inside the step: stick where θ̇ = 0
            const double share = rate0 != rate1 ? std::clamp(rate0 / (rate0 - rate1), 0.0, 1.0) : 0.0;
            const double rest = angle0 + share * (angle1 - angle0);
            after[kFrictionSwitched] = 1.0;
            return to(HingeMode::stuck, rest, ElementEventKind::stuck, rest);
          }
        }
        return false;
      }
      case HingeMode::stuck: {
        const double capacity = e.friction_coefficient * e.pin_radius_m * r.pin_force(q1, t).magnitude_N;
        if (std::abs(lock) <= capacity || before[kFrictionSwitched] != 0.0) return false;
        after[kSlip] = sign_of(lock);  // it slides the way the lock was holding it from
        after[kFrictionSwitched] = 1.0;
        return to(HingeMode::free, before[kLockAngle], ElementEventKind::slipping, -lock);
      }
      case HingeMode::stop_min:  // a stop only pushes: λ < 0 resists θ falling
        if (lock <= 0.0) return false;
        after[kSlip] = e.friction_coefficient > 0.0 ? 1.0 : 0.0;
        return to(HingeMode::free, before[kLockAngle], ElementEventKind::released, before[kLockAngle]);
      case HingeMode::stop_max:
        if (lock >= 0.0) return false;
        after[kSlip] = e.friction_coefficient > 0.0 ? -1.0 : 0.0;
        return to(HingeMode::free, before[kLockAngle], ElementEventKind::released, before[kLockAngle]);
      case HingeMode::held:  // released at t = 0: the first step again, free
        after[kSlip] = e.friction_coefficient > 0.0 ? sign_of(lock) : 0.0;
        return to(HingeMode::free, before[kLockAngle], ElementEventKind::released, before[kLockAngle]);
      case HingeMode::latched:
        return false;
    }
    return false;
  }

  // Dissipated energy by the trapezoidal rule in θ, ½ (T_n + T_{n+1}) (θ_{n+1} − θ_n), of the
  // resisting damper, friction and lock torques; the lock torque and the sliding direction at
  // the step's end.
  void accumulate(KinematicsLease& lease, std::size_t i, const StepEnds& ends, std::span<const double> before,
                  std::span<double> after) const {
    const HingeRecord& r = records_[i];
    const auto mode = static_cast<HingeMode>(static_cast<int>(before[kMode]));
    const HingeVector q1 = r.gather(ends.q_after), v1 = r.gather(ends.v_after);
    const HingeKinematics& k1 = lease.at(i, q1, false);
    const double angle0 = lease.angle(i, r.gather(ends.q_before));
    lease.remember_step_end(i, q1, k1.angle_rad);
    const double slip = mode == HingeMode::free && r.element->friction_coefficient > 0.0 ? before[kSlip] : 0.0;
    const HingeTorques torques = rate_torques(r, k1, q1, v1, ends.time_after_s, slip);
    const double lock = lock_torque(i, mode, ends);
    double loss = torques.damper + torques.friction + lock;
    if (!sites_[i].empty()) {  // the contacts' damping, with the modes of the step (before)
      const ContactTorques c = contact_torques(i, before, k1.angle_rad, k1.gradient.dot(v1));
      loss += c.total - c.elastic;
    }
    after[kDissipated] = before[kDissipated] + 0.5 * (before[kLossTorque] + loss) * (k1.angle_rad - angle0);
    after[kLossTorque] = loss;
    after[kLockTorque] = lock;
    after[kFrictionSwitched] = 0.0;
    // The direction friction resists in the next step: the hinge's motion now (with drivers,
    // also through a reversal, as no hinge sticks then).
    const double rate1 = k1.gradient.dot(v1);
    const bool may_turn_over = driven_ || before[kSlip] == 0.0;
    if (mode == HingeMode::free && r.element->friction_coefficient > 0.0 && rate1 != 0.0 &&
        (may_turn_over || sign_of(rate1) == before[kSlip])) {
      after[kSlip] = sign_of(rate1);
    }
  }

  std::vector<HingeRecord> records_;
  std::vector<std::string> labels_;  // "hinge <name>", for messages
  bool driven_ = false;
  std::vector<int> lock_index_;  // [hinge] → its lock among make_switched_constraints(), −1 without
  std::vector<std::vector<ContactSite>> sites_;  // [hinge] → its compliant stops and latch
  mutable std::vector<KinematicsSlots> kinematics_;  // [hinge], KinematicsLease
  mutable std::atomic_flag kinematics_in_use_;
};

}  // namespace

std::unique_ptr<ElementGroup> make_hinge_group(const Model& model, const DofMap& dofs) {
  std::vector<HingeRecord> records;
  std::vector<std::string> labels;
  const int dimension = model.dimension;
  for (const HingeElement& e : model.hinges) {
    const std::string label = "hinge " + e.name;
    HingeRecord& r = records.emplace_back();
    r.element = &e;
    r.dimension = dimension;
    labels.push_back(label);
    if (e.form == HingeElement::Form::rotations) {
      for (const int node : {e.nodes[0], e.nodes[1]}) {
        const int rz = dofs.index(node, "rz");
        if (rz < 0) {
          throw std::invalid_argument(label + ": node " + model.nodes[node].name +
                                      " carries no rotation (rotation_nodes need beam nodes of a 2D model)");
        }
        r.dofs.push_back(rz);
      }
      continue;
    }
    for (const int node : e.nodes) {
      for (int axis = 0; axis < dimension; ++axis) r.dofs.push_back(dofs.index(node, axis));
    }
    r.geometry = HingeAngle(dimension == 2 ? Eigen::Vector3d::UnitZ() : e.axis);
    const Eigen::Vector3d& h = model.nodes[e.nodes[1]].position_m;
    r.reference_length_m = std::min((model.nodes[e.nodes[0]].position_m - h).norm(),
                                    (model.nodes[e.nodes[2]].position_m - h).norm());
    if (e.friction_coefficient == 0.0) continue;
    // Friction presses with the axial force of the bar A–H.
    const auto member = std::find_if(model.bars.begin(), model.bars.end(), [&](const BarElement& b) {
      return (b.node_a == e.nodes[0] && b.node_b == e.nodes[1]) || (b.node_a == e.nodes[1] && b.node_b == e.nodes[0]);
    });
    if (member == model.bars.end()) {
      throw std::invalid_argument(label + ": friction needs a bar between its nodes " + model.nodes[e.nodes[0]].name +
                                  " and " + model.nodes[e.nodes[1]].name + " (A and H): its axial force is the pin force");
    }
    const Material& material = model.materials[member->material];
    r.pin_member = PinMember{{material.youngs_modulus_Pa * member->area_m2, member->reference_length_m},
                             material.expansion_per_C, &member->temperature_change_C,
                             MaterialLaw(material, reference_temperature_C(model)), member->area_m2};
  }
  return std::make_unique<HingeGroup>(std::move(records), std::move(labels), !model.drivers.empty());
}

}  // namespace deploydyn
