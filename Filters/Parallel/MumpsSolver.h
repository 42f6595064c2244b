// MumpsSolver: factors across the MPI processes of a controller with MUMPS.
//
// The distributed solver of vtkPLaplacianDeformationFilter (LaplacianEditing::DistributedSolver).
// Every MUMPS call is collective, but only the first process runs the edit and knows when a
// factorization or a solve is due. So, during an update, the other processes wait in Serve()
// for the first one's commands and make the same MUMPS calls with it, until it calls
// EndService(). Each factor is one MUMPS instance on every process, under the same number; a
// factor the first process drops is released on all of them at the next command. Processes
// that share a machine share its memory: a factor whose estimated shares do not fit a machine
// is refused with an error after the analysis, before it is attempted.

#ifndef LaplacianEditing_Parallel_MumpsSolver_h
#define LaplacianEditing_Parallel_MumpsSolver_h

#include "DistributedSolver.h"

#include "vtkMPI.h"                    // for MPI_Comm
#include "vtkMultiProcessController.h" // for vtkSmartPointer<vtkMultiProcessController>
#include "vtkSmartPointer.h"

#include <map>
#include <memory>
#include <vector>

namespace LaplacianEditing
{
namespace Parallel
{
class MumpsSolver
  : public DistributedSolver
  , public std::enable_shared_from_this<MumpsSolver>
{
public:
  /// A solver over the controller's processes; nullptr unless it runs over MPI.
  static std::shared_ptr<MumpsSolver> New(vtkMultiProcessController* controller);
  /// Releases every instance; collective, as the filters are deleted on every process.
  ~MumpsSolver() override;

  std::unique_ptr<DistributedFactor> Factorize(
    const Eigen::SparseMatrix<double>& matrix, std::string& error) override;
  int GetNumberOfProcesses() const override;

  /// The other processes: make the first one's MUMPS calls until it ends the service.
  void Serve();
  /// The first process: the update's factorizations and solves are over.
  void EndService();

  /// The first process's share of a solve (used by its factors).
  Eigen::MatrixXd Solve(int instance, const Eigen::MatrixXd& rhs);
  /// The first process: the factor is gone; its instance is released at the next command.
  void Release(int instance);

  struct Instance;

private:
  explicit MumpsSolver(vtkMultiProcessController* controller);
  enum Command
  {
    FACTORIZE,
    SOLVE,
    RELEASE,
    END
  };
  /// The first process tells the others what to call next (after the releases due).
  void Send(Command command, int instance, int columns);
  /// Creates an instance, analyses and, if the machines can hold it, factors (the matrix on the
  /// first process only); the instance is dropped again if that fails. Returns INFOG(1).
  int Factor(int instance, const Eigen::SparseMatrix<double>* matrix);
  void Run(Instance& instance, int job) const;
  void End(int instance);
  /// Whether the analysed factor's shares fit the memory of the machines that hold them; sets
  /// MachineNeed and MachineLimit to the figures of the machine with the least room.
  bool FitsTheMachines(const Instance& instance);

  vtkSmartPointer<vtkMultiProcessController> Controller;
  MPI_Comm Communicator = MPI_COMM_NULL;
  MPI_Comm MachineCommunicator = MPI_COMM_NULL; // the processes on this one's machine
  int FortranCommunicator = 0;
  std::map<int, std::unique_ptr<Instance>> Instances;
  std::vector<int> Released;
  int NextInstance = 0;
  double MachineNeed = 0.0;  // MB
  double MachineLimit = 0.0; // MB
};
}
}

#endif
