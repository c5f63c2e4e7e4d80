#pragma once
// The processes of one run started by mpirun, through VTK's MPI controller (vtkMPIController):
// they share the work folder and split the per-frame work. A process started otherwise, or a
// build without MPI, is the only one.
#include <string>
#include <vector>

namespace clothtrack::app
{
namespace ranks
{
/// Starts MPI when mpirun started this process (and the build has MPI); else nothing.
void start(int* argc, char*** argv);
/// Ends MPI (every process, after its last message).
void stop();
/// Ends every process with exit code 1: an error on one would leave the others waiting.
[[noreturn]] void abortAll();
int rank();    ///< this process, 0 .. count() - 1
int count();   ///< processes sharing the run
bool leader(); ///< process 0: it reads, writes the shared files and evaluates
/// Waits until every process has come here.
void barrier();
/// Element-wise sum over the processes, on every process.
void sum(std::vector<double>& values);
/// Each process's `values` (the same length on all), process 0's first, on every process.
std::vector<double> gather(const std::vector<double>& values);
/// Each process's bytes (any length), process 0's first, on every process.
std::vector<std::string> gatherBytes(const std::string& bytes);
} // namespace ranks
} // namespace clothtrack::app
