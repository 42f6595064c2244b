#include "MumpsSolver.h"

#include "SolverSettings.h"
#include "vtkMPI.h"
#include "vtkMPICommunicator.h"
#include "vtkMultiProcessController.h"

#include <dmumps_c.h>

#include <cmath>
#include <string>

namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Parallel
{

struct MumpsSolver::Instance
{
  DMUMPS_STRUC_C Mumps{};
  // MUMPS's arrays are one-based (ICNTL(I) is icntl[I - 1]).
  MUMPS_INT& Control(int i) { return this->Mumps.icntl[i - 1]; }
  MUMPS_INT Info(int i) const { return this->Mumps.infog[i - 1]; }
  // INFOG fields that count millions when negative.
  double Count(int i) const
  {
    const MUMPS_INT value = this->Info(i);
    return value < 0 ? -1e6 * value : static_cast<double>(value);
  }
};

namespace
{
const int JobInitialize = -1;
const int JobEnd = -2;
const int JobAnalyze = 1;
const int JobFactorize = 2;
const int JobSolve = 3;
// Our own status for a factor that would not fit the machines' memory.
const int TooLargeForTheMachines = -100000;

class MumpsFactor : public le::DistributedFactor
{
public:
  MumpsFactor(std::shared_ptr<MumpsSolver> solver, int instance, double bytes)
    : Solver(std::move(solver))
    , Number(instance)
    , Bytes(bytes)
  {
  }
  ~MumpsFactor() override { this->Solver->Release(this->Number); }
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs) const override
  {
    return this->Solver->Solve(this->Number, rhs);
  }
  double GetBytes() const override { return this->Bytes; }

private:
  std::shared_ptr<MumpsSolver> Solver;
  int Number;
  double Bytes;
};

bool MPIRunning()
{
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}
}

std::shared_ptr<MumpsSolver> MumpsSolver::New(
  vtkMultiProcessController* controller)
{
  auto* communicator =
    controller ? vtkMPICommunicator::SafeDownCast(controller->GetCommunicator()) : nullptr;
  if (!communicator || !communicator->GetMPIComm() || !MPIRunning())
  {
    return nullptr;
  }
  std::shared_ptr<MumpsSolver> solver(new MumpsSolver(controller));
  solver->Communicator = *communicator->GetMPIComm()->GetHandle();
  solver->FortranCommunicator = static_cast<int>(MPI_Comm_c2f(solver->Communicator));
  // Collective: every process makes its solver in the same update.
  MPI_Comm_split_type(solver->Communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL,
    &solver->MachineCommunicator);
  return solver;
}

MumpsSolver::MumpsSolver(vtkMultiProcessController* controller)
  : Controller(controller)
{
}

MumpsSolver::~MumpsSolver()
{
  // After MPI_Finalize the process is ending and MUMPS can no longer be called.
  if (MPIRunning())
  {
    while (!this->Instances.empty())
    {
      this->End(this->Instances.begin()->first);
    }
    MPI_Comm_free(&this->MachineCommunicator);
  }
}

int MumpsSolver::GetNumberOfProcesses() const
{
  return this->Controller->GetNumberOfProcesses();
}

void MumpsSolver::Run(Instance& instance, int job) const
{
  instance.Mumps.job = job;
  dmumps_c(&instance.Mumps);
}

void MumpsSolver::End(int number)
{
  auto found = this->Instances.find(number);
  if (found != this->Instances.end())
  {
    this->Run(*found->second, JobEnd);
    this->Instances.erase(found);
  }
}

void MumpsSolver::Send(Command command, int instance, int columns)
{
  for (const int released : this->Released)
  {
    int message[3] = { RELEASE, released, 0 };
    this->Controller->Broadcast(message, 3, 0);
    this->End(released);
  }
  this->Released.clear();
  int message[3] = { command, instance, columns };
  this->Controller->Broadcast(message, 3, 0);
}

int MumpsSolver::Factor(int number, const Eigen::SparseMatrix<double>* matrix)
{
  auto instance = std::make_unique<Instance>();
  DMUMPS_STRUC_C& mumps = instance->Mumps;
  mumps.comm_fortran = this->FortranCommunicator;
  mumps.par = 1; // the first process works on the factor too
  mumps.sym = 1; // symmetric positive definite
  this->Run(*instance, JobInitialize);
  // Quiet: errors come back through INFOG(1) and become the filter's messages.
  instance->Control(1) = -1;
  instance->Control(2) = -1;
  instance->Control(3) = -1;
  instance->Control(4) = 0;
  std::vector<MUMPS_INT> rows, columns;
  std::vector<double> values;
  if (matrix)
  {
    // The upper triangle, as CHOLMOD reads it, in one-based coordinates.
    for (Eigen::Index column = 0; column < matrix->outerSize(); ++column)
    {
      for (Eigen::SparseMatrix<double>::InnerIterator it(*matrix, column); it; ++it)
      {
        if (it.row() <= column)
        {
          rows.push_back(static_cast<MUMPS_INT>(it.row() + 1));
          columns.push_back(static_cast<MUMPS_INT>(column + 1));
          values.push_back(it.value());
        }
      }
    }
    mumps.n = static_cast<MUMPS_INT>(matrix->rows());
    mumps.nnz = static_cast<MUMPS_INT8>(values.size());
    mumps.irn = rows.data();
    mumps.jcn = columns.data();
    mumps.a = values.data();
  }
  this->Run(*instance, JobAnalyze);
  if (instance->Info(1) >= 0 && !this->FitsTheMachines(*instance))
  {
    instance->Mumps.infog[0] = TooLargeForTheMachines;
  }
  else
  {
    this->Run(*instance, JobFactorize);
  }
  mumps.irn = mumps.jcn = nullptr;
  mumps.a = nullptr;
  // INFOG(1) is the same on every process: all of them drop a failed instance.
  const int status = instance->Info(1);
  this->Instances[number] = std::move(instance);
  if (status < 0)
  {
    this->End(number);
  }
  return status;
}

bool MumpsSolver::FitsTheMachines(const Instance& instance)
{
  // Processes on one machine share its memory: the shares MUMPS's analysis estimates for them
  // (INFO(15), megabytes) must fit together in 80% of what it has available, the filter's
  // automatic limit, on every machine.
  const int share = instance.Mumps.info[14];
  int onThisMachine = 0;
  MPI_Allreduce(&share, &onThisMachine, 1, MPI_INT, MPI_SUM, this->MachineCommunicator);
  const double available = Pipeline::SolverSettings::AutomaticFactorLimit();
  // The machine that lacks the most reports its figures.
  struct
  {
    double Value;
    int Rank;
  } shortfall{ onThisMachine - available, 0 }, largest{ 0.0, 0 };
  MPI_Comm_rank(this->Communicator, &shortfall.Rank);
  MPI_Allreduce(&shortfall, &largest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, this->Communicator);
  double figures[2] = { static_cast<double>(onThisMachine), available };
  MPI_Bcast(figures, 2, MPI_DOUBLE, largest.Rank, this->Communicator);
  this->MachineNeed = figures[0];
  this->MachineLimit = figures[1];
  return largest.Value <= 0.0;
}

std::unique_ptr<le::DistributedFactor> MumpsSolver::Factorize(
  const Eigen::SparseMatrix<double>& matrix, std::string& error)
{
  const int number = this->NextInstance++;
  this->Send(FACTORIZE, number, 0);
  const int status = this->Factor(number, &matrix);
  if (status < 0)
  {
    // -10: a zero or negative pivot, as CHOLMOD's "not positive definite".
    const std::string processes = std::to_string(this->GetNumberOfProcesses()) + " processes";
    if (status == TooLargeForTheMachines)
    {
      error = "MUMPS estimates that the shares of the factor across " + processes + " need " +
        std::to_string(static_cast<long>(this->MachineNeed)) + " MB on one machine, more than " +
        "the " + std::to_string(static_cast<long>(this->MachineLimit)) +
        " MB it may use (80% of what it has available); choose a smaller region of interest " +
        "or spread the ranks over more machines";
    }
    else if (status == -10)
    {
      error = "the normal equations are not positive definite: some part of the region is not "
              "held by any constraint";
    }
    else
    {
      error = "MUMPS failed to factor across " + processes + " (INFOG(1) = " +
        std::to_string(status) + ")";
    }
    return nullptr;
  }
  const Instance& instance = *this->Instances[number];
  // INFOG(29): the factor's entries on all processes.
  return std::make_unique<MumpsFactor>(this->shared_from_this(), number, 8.0 * instance.Count(29));
}

Eigen::MatrixXd MumpsSolver::Solve(int number, const Eigen::MatrixXd& rhs)
{
  this->Send(SOLVE, number, static_cast<int>(rhs.cols()));
  Instance& instance = *this->Instances.at(number);
  Eigen::MatrixXd solution = rhs;
  instance.Mumps.nrhs = static_cast<MUMPS_INT>(rhs.cols());
  instance.Mumps.lrhs = static_cast<MUMPS_INT>(rhs.rows());
  instance.Mumps.rhs = solution.data();
  this->Run(instance, JobSolve);
  instance.Mumps.rhs = nullptr;
  return solution;
}

void MumpsSolver::Release(int number)
{
  this->Released.push_back(number);
}

void MumpsSolver::EndService()
{
  if (this->GetNumberOfProcesses() > 1)
  {
    this->Send(END, 0, 0);
  }
}

void MumpsSolver::Serve()
{
  for (;;)
  {
    int message[3] = { END, 0, 0 };
    this->Controller->Broadcast(message, 3, 0);
    switch (message[0])
    {
      case FACTORIZE:
        this->Factor(message[1], nullptr);
        break;
      case SOLVE:
      {
        auto found = this->Instances.find(message[1]);
        if (found != this->Instances.end())
        {
          found->second->Mumps.nrhs = message[2];
          this->Run(*found->second, JobSolve);
        }
        break;
      }
      case RELEASE:
        this->End(message[1]);
        break;
      default:
        return;
    }
  }
}
}
}
