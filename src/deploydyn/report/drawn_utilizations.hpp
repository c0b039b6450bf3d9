#pragma once
// The report's colours by utilization: for each member the page draws (an element with two
// nodes), the largest utilization of its checks at a history row, from the forces history.csv
// holds, Eqs. (V1)–(V5) of docs/theory.md, "Member checks and the verdict", through the same
// element_utilizations as the run's own checks (checks/member_checks.hpp). At output times
// only: the run's verdict (summary.json) is taken at every step.

#include <functional>
#include <string>
#include <vector>

#include "deploydyn/checks/member_checks.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

class DrawnUtilizations {
 public:
  // `drawn`: the drawn elements' names; `column(name)`: the index of a history column, −1 when
  // the history has none of that name.
  DrawnUtilizations(const Model& model, const std::vector<std::string>& drawn,
                    const std::function<int(const std::string&)>& column);

  // Whether some drawn element has a check that runs (a capacity given) and its force.
  bool any() const { return any_; }
  // A beam's stress check runs but its bending moments, shear forces or torque are not in the
  // history (output.select): its utilization then leaves them out.
  bool forces_missing() const { return forces_missing_; }
  // The largest utilization of drawn element `i` at the row whose column values `value` gives,
  // at `time_s`; NaN when none of its checks runs or its force is not in the history. Its Euler
  // load at E(T): `temperature_K` its temperature there (temperatures.csv of a run with an
  // environment), NaN when not known: then its ΔT(t) in the model, as the run's checks take it.
  double at(std::size_t i, const std::function<double(int column)>& value, double time_s,
            double temperature_K) const;

 private:
  struct Drawn {
    int member = -1;   // into members_; −1: none (a hinge, an element of no checked kind)
    int element = -1;  // into that member's elements
    ChecksThatRun runs{};
    int force = -1, moment_z = -1, moment_y = -1, shear_y = -1, shear_z = -1, torque = -1;  // history columns
  };
  int dimension_ = 2;
  double reference_temperature_K_ = 0.0;  // the environment's T_ref; NaN without one
  std::vector<CheckedMember> members_;
  std::vector<Drawn> drawn_;
  bool any_ = false;
  bool forces_missing_ = false;
};

}  // namespace deploydyn
