// Running a program under mpirun from a test (tests/*_mpi_test.cc): the launcher CMake found
// (DRAPE_MPIEXEC, empty when drape is built without MPI), a time limit so that a hang fails the
// test instead of stalling it, and the program's stdout, stderr and exit status. As root, Open
// MPI needs OMPI_ALLOW_RUN_AS_ROOT=1 and OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1, and 3 ranks on 2 cores
// need OMPI_MCA_rmaps_base_oversubscribe=1: CTest sets them (CMakeLists.txt, drape_mpi_tests).
#pragma once

#include <string>

#include "tests/run_program.h"

namespace drape::testing {

// Whether tests can run mpirun: built with MPI and the launcher found.
inline bool MpiLauncherAvailable() { return std::string(DRAPE_MPIEXEC).size() > 0; }

// `timeout 120 mpirun -np N` (the time limit turns a hang into exit status 124; the runs of the
// tests take a few seconds).
inline std::string MpiRun(int ranks) {
  return "timeout 120 " + std::string(DRAPE_MPIEXEC) + " -np " + std::to_string(ranks) + " ";
}

}  // namespace drape::testing
