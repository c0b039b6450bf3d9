// Loads a model with the installed deploydyn, runs its first 0.05 s into a folder and checks the
// run completed and wrote one history row per output time. Usage: consumer MODEL OUT_DIR.

#include <deploydyn/io/model_loader.hpp>
#include <deploydyn/runs/run_to_folder.hpp>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: consumer MODEL OUT_DIR\n";
    return 2;
  }
  const deploydyn::Model model = deploydyn::load_model(argv[1], {{"analysis.end", "0.05"}});
  const deploydyn::RunReport report = deploydyn::run_to_folder(model, argv[2]);
  std::cout << report.message << '\n';
  if (report.status != deploydyn::RunStatus::completed || report.time_reached_s != 0.05) return 1;

  std::ifstream history(std::string(argv[2]) + "/" + model.output.history_file);
  int n_lines = 0;
  for (std::string line; std::getline(history, line);) ++n_lines;
  const int expected = 1 + 11;  // the header, then t = 0, 0.005, ..., 0.05
  if (n_lines != expected) {
    std::cerr << "history has " << n_lines << " lines, expected " << expected << '\n';
    return 1;
  }
  std::cout << "consumer: " << model.name << ", " << model.n_bars() << " bars, node B starts at "
            << model.nodes[1].position_m.transpose() << " m\n";
  return 0;
}
