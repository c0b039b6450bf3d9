// `deploydyn study` under mpirun, when it cannot start: a bad study file, a folder in use, an
// --out that cannot be written. Issue 32: each printed nothing but Open MPI's MPI_ABORT banner.
// The message must come once, with the command's exit code. Skipped without mpirun or MPI.

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::ScratchFolder;

bool mpi_available() {
  // MPI is in a module beside the command's build (util/optional_module.hpp), loaded under mpirun.
  return std::system("command -v mpirun >/dev/null 2>&1") == 0 &&
         std::filesystem::exists(std::filesystem::path(DEPLOYDYN_CLI).parent_path() / "modules" / "deploydyn_mpi.so");
}

// mpirun as python/tests/test_mpi_study.py runs it: two processes, as root if need be.
testing::CliOutcome mpirun_study(const std::string& arguments) {
  return testing::run_cli_with_prefix(
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 120 mpirun -n 2 --oversubscribe",
      "study " + arguments + " --quiet");
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(CliMpi, ABadStudyFileIsToldOnceAndEveryProcessExitsWithTwo) {
  if (!mpi_available()) GTEST_SKIP() << "needs mpirun and deploydyn's MPI module";
  if (testing::kCliUnderAddressSanitizer) GTEST_SKIP() << "LeakSanitizer reports OpenMPI's own allocations";
  const ScratchFolder folder("mpi_bad_key");
  std::filesystem::create_directories(folder.path());
  const auto study = folder.path() / "bad.yaml";
  std::ofstream(study) << "model: " << example_path("general.yaml") << "\ncases: {a: {thermal.dT: 1}}\nbogus: 1\n";
  const auto outcome = mpirun_study(study.string() + " --out " + (folder.path() / "out").string());
  EXPECT_EQ(outcome.exit_code, 2) << outcome.output;
  EXPECT_EQ(count(outcome.output, "bad.yaml:3:1: bogus: unknown key 'bogus'"), 1u) << outcome.output;
  EXPECT_EQ(outcome.output.find("MPI_ABORT"), std::string::npos) << outcome.output;
}

TEST(CliMpi, AnOutThatCannotBeWrittenIsToldWithExitCodeThree) {
  if (!mpi_available()) GTEST_SKIP() << "needs mpirun and deploydyn's MPI module";
  if (testing::kCliUnderAddressSanitizer) GTEST_SKIP() << "LeakSanitizer reports OpenMPI's own allocations";
  const ScratchFolder folder("mpi_unwritable");
  std::filesystem::create_directories(folder.path());
  std::ofstream(folder.path() / "file") << "a file, not a folder\n";
  const auto outcome = mpirun_study(example_path("general_study.yaml") + " --out " +
                                    (folder.path() / "file" / "out").string());
  EXPECT_EQ(outcome.exit_code, 3) << outcome.output;
  EXPECT_EQ(count(outcome.output, "cannot create folder"), 1u) << outcome.output;
  EXPECT_NE(outcome.output.find("Not a directory"), std::string::npos) << outcome.output;
}

TEST(CliMpi, AFolderInUseIsToldWithExitCodeThree) {
  if (!mpi_available()) GTEST_SKIP() << "needs mpirun and deploydyn's MPI module";
  if (testing::kCliUnderAddressSanitizer) GTEST_SKIP() << "LeakSanitizer reports OpenMPI's own allocations";
  const ScratchFolder folder("mpi_in_use");
  std::filesystem::create_directories(folder.path());
  // This test holds the folder's lock, as a study running into it would.
  const int lock = open((folder.path() / ".deploydyn.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(lock, 0);
  ASSERT_EQ(flock(lock, LOCK_EX | LOCK_NB), 0);
  const auto outcome = mpirun_study(example_path("general_study.yaml") + " --out " + folder.path().string());
  close(lock);
  EXPECT_EQ(outcome.exit_code, 3) << outcome.output;
  EXPECT_EQ(count(outcome.output, "error: "), 1u) << outcome.output;
  EXPECT_NE(outcome.output.find(folder.path().string()), std::string::npos) << outcome.output;
}

}  // namespace
}  // namespace deploydyn
