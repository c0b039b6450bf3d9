#pragma once
// A one-line note on stderr of what a long command is doing ("generate roof: writing the
// model text …"), each phase replacing the last and the line cleared when done; shown only
// when stderr is a terminal, as run's progress line (app/main.cpp).

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <string_view>

namespace deploydyn::cli {

class PhaseLine {
 public:
  PhaseLine() : enabled_(isatty(fileno(stderr)) != 0) {}
  ~PhaseLine() { clear(); }
  PhaseLine(const PhaseLine&) = delete;
  PhaseLine& operator=(const PhaseLine&) = delete;

  void show(std::string_view text) {
    if (!enabled_) return;
    clear();
    fmt::print(stderr, "\r  {} …", text);
    std::fflush(stderr);
    width_ = text.size() + 6;
  }
  void clear() noexcept {
    if (width_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(width_), "");
    width_ = 0;
  }

 private:
  bool enabled_;
  std::size_t width_ = 0;  // of the line shown, 0 when none
};

}  // namespace deploydyn::cli
