#include "deploydyn/study/study.hpp"

#include <algorithm>
#include <thread>

namespace deploydyn {

std::filesystem::path Study::case_folder(std::size_t index) const {
  return out_folder / cases.at(index).name;
}

std::filesystem::path Study::table_file() const { return out_folder / kStudyTableFileName; }

int resolve_jobs(int jobs, std::size_t n_cases) {
  // hardware_concurrency() may be 0 when it cannot tell.
  const int wanted =
      jobs > 0 ? jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return static_cast<int>(std::clamp<std::size_t>(static_cast<std::size_t>(wanted), 1,
                                                  std::max<std::size_t>(n_cases, 1)));
}

}  // namespace deploydyn
