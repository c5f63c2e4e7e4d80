#include "Ranks.h"

#include <algorithm>
#include <cstdlib>

#ifdef CLOTHTRACK_WITH_MPI
#include <vtkMPIController.h>
#include <vtkSmartPointer.h>

#include <mpi.h>
#endif

namespace clothtrack::app::ranks
{
#ifdef CLOTHTRACK_WITH_MPI
namespace
{
vtkSmartPointer<vtkMPIController>& controller()
{
  static vtkSmartPointer<vtkMPIController> instance;
  return instance;
}

/// mpirun (Open MPI, MPICH, Slurm's PMI) says so in the environment of the processes it starts.
bool startedByMpirun()
{
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}
} // namespace

void start(int* argc, char*** argv)
{
  if (!startedByMpirun()) return;
  controller() = vtkSmartPointer<vtkMPIController>::New();
  controller()->Initialize(argc, argv);
  vtkMultiProcessController::SetGlobalController(controller());
}

void stop()
{
  if (!controller()) return;
  controller()->Finalize();
  vtkMultiProcessController::SetGlobalController(nullptr);
  controller() = nullptr;
}

void abortAll()
{
  if (controller() && controller()->GetNumberOfProcesses() > 1) MPI_Abort(MPI_COMM_WORLD, 1);
  std::exit(1);
}

int rank()
{
  return controller() ? controller()->GetLocalProcessId() : 0;
}

int count()
{
  return controller() ? controller()->GetNumberOfProcesses() : 1;
}

void barrier()
{
  if (count() > 1) controller()->Barrier();
}

void sum(std::vector<double>& values)
{
  if (count() == 1 || values.empty()) return;
  std::vector<double> total(values.size());
  controller()->AllReduce(values.data(), total.data(), static_cast<vtkIdType>(values.size()),
                          vtkCommunicator::SUM_OP);
  values = std::move(total);
}

std::vector<double> gather(const std::vector<double>& values)
{
  if (count() == 1 || values.empty()) return values;
  std::vector<double> all(values.size() * count());
  controller()->AllGather(values.data(), all.data(), static_cast<vtkIdType>(values.size()));
  return all;
}

std::vector<std::string> gatherBytes(const std::string& bytes)
{
  if (count() == 1) return {bytes};
  const vtkIdType length = static_cast<vtkIdType>(bytes.size());
  std::vector<vtkIdType> lengths(count()), offsets(count());
  controller()->AllGather(&length, lengths.data(), 1);
  vtkIdType total = 0;
  for (int r = 0; r < count(); ++r)
  {
    offsets[r] = total;
    total += lengths[r];
  }
  std::vector<char> all(std::max<vtkIdType>(total, 1));
  controller()->AllGatherV(bytes.data(), all.data(), length, lengths.data(), offsets.data());
  std::vector<std::string> out;
  for (int r = 0; r < count(); ++r) out.emplace_back(all.data() + offsets[r], lengths[r]);
  return out;
}
#else
void start(int*, char***) {}
void stop() {}
void abortAll()
{
  std::exit(1);
}
int rank()
{
  return 0;
}
int count()
{
  return 1;
}
void barrier() {}
void sum(std::vector<double>&) {}
std::vector<double> gather(const std::vector<double>& values)
{
  return values;
}
std::vector<std::string> gatherBytes(const std::string& bytes)
{
  return {bytes};
}
#endif

bool leader()
{
  return rank() == 0;
}
} // namespace clothtrack::app::ranks
