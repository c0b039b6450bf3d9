#pragma once
// What `deploydyn check` says of the member checks before anything runs: the members, and per
// kind of check the members it will run on, the governing capacity, and what the others lack
// (docs/model-format.md, `members`). A few lines, whatever the model's size.

#include <functional>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// `list` shortens a list of names for one screen (the CLI's; all of them with --all).
std::vector<std::string> capacity_lines(const Model& model,
                                        const std::function<std::string(const std::vector<std::string>&)>& list);

}  // namespace deploydyn
