// Running a program under mpirun from a test (tests/*_mpi_test.cc): the launcher CMake found
// (DRAPE_MPIEXEC, empty when drape is built without MPI), a time limit so that a hang fails the
// test instead of stalling it, and the program's stdout, stderr and exit status. As root, Open
// MPI needs OMPI_ALLOW_RUN_AS_ROOT=1 and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1, and 3 ranks on 2 cores
// need OMPI_MCA_rmaps_base_oversubscribe=1: CTest sets them (CMakeLists.txt, drape_mpi_tests).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "src/output/csv_field.h"
#include "src/sweep/sweep.h"
#include "tests/run_program.h"

namespace drape::testing {

// Whether tests can run mpirun: built with MPI and the launcher found.
inline bool MpiLauncherAvailable() { return std::string(DRAPE_MPIEXEC).size() > 0; }

// `timeout 120 mpirun -np N` (the time limit turns a hang into exit status 124; the runs of the
// tests take a few seconds).
inline std::string MpiRun(int ranks) {
  return "timeout 120 " + std::string(DRAPE_MPIEXEC) + " -np " + std::to_string(ranks) + " ";
}

// A CSV file of drape's as cells, without the column `varying` (a solve's time, which differs
// from run to run): what the MPI tests compare between the process alone and the ranks.
inline std::vector<std::vector<std::string>> CsvRowsWithout(const std::filesystem::path& csv,
                                                            const std::string& varying) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(csv);
  std::string line;
  int column = -1;
  while (std::getline(in, line)) {
    auto cells = SplitCsvLine(line);
    if (rows.empty()) {
      for (size_t k = 0; k < cells.size(); ++k) {
        if (cells[k] == varying) column = static_cast<int>(k);
      }
    }
    if (column >= 0) cells.erase(cells.begin() + column);
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace drape::testing
