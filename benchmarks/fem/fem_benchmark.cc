// Far-field throughput on the paper slab (50 x 10 x 50 mm) with a 10 x 10 mm MPM hole through
// the thickness: set-up time, explicit steps (quadrature-point updates per second) and
// implicit Newmark steps with the multigrid hierarchy rebuilt every solve and reused, and with
// a sparse LU (Newton and linear iterations, seconds per step split into assembly, set-up and
// solve).
// Usage: fem_benchmark [interface_cell_size_m=1e-3] [far_cell_size_m=2e-3] [grading=1.15]
//                      [explicit_steps=50] [implicit_steps=2]
#include "fem/far_field_solver.h"

#include <deal.II/base/mpi.h>

#include <chrono>
#include <omp.h>
#include <cstdlib>
#include <iostream>

namespace
{
double seconds_since(const std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace

int main(int argc, char** argv)
{
  using namespace vulnus::fem;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  FeSceneParameters p;
  p.has_hole = true;
  p.hole_min = {{0.02, 0.0, 0.02}};
  p.hole_max = {{0.03, 0.01, 0.03}};
  p.interface_cell_size = argc > 1 ? std::atof(argv[1]) : 1e-3;
  p.far_cell_size = argc > 2 ? std::atof(argv[2]) : 2e-3;
  p.grading_ratio = argc > 3 ? std::atof(argv[3]) : 1.15;
  const unsigned int n_explicit = argc > 4 ? std::atoi(argv[4]) : 50;
  const unsigned int n_implicit = argc > 5 ? std::atoi(argv[5]) : 2;
  p.interface_condition = InterfaceCondition::velocity_driven;
  p.fibers.kind = vulnus::materials::FiberFieldParameters::Kind::rotating;

  struct Case
  {
    TimeIntegrator integrator;
    bool reuse_preconditioner;
    LinearSolverType linear_solver;
  };
  for (const Case run_case :
       {Case{TimeIntegrator::central_difference, true, LinearSolverType::cg},
        Case{TimeIntegrator::newmark, false, LinearSolverType::cg},
        Case{TimeIntegrator::newmark, true, LinearSolverType::cg},
        Case{TimeIntegrator::newmark, true, LinearSolverType::direct}})
  {
    const TimeIntegrator integrator = run_case.integrator;
    p.integrator = integrator;
    p.reuse_preconditioner = run_case.reuse_preconditioner;
    p.linear_solver = run_case.linear_solver;
    p.time_step = 1e-5;
    const auto t0 = std::chrono::steady_clock::now();
    FarFieldSolver solver(p, MPI_COMM_WORLD);
    solver.setup();
    const double setup = seconds_since(t0);
    std::vector<dealii::Tensor<1, 3>> v(solver.interface_nodes().size());
    for (auto& w : v)
      w[1] = 0.1; // m/s: the tract wall dragged along the bullet path
    solver.set_interface_velocities(v);
    const bool implicit = integrator != TimeIntegrator::central_difference;
    const unsigned int n_steps = implicit ? n_implicit : n_explicit;
    const auto t1 = std::chrono::steady_clock::now();
    unsigned int newton = 0, linear = 0, setups = 0;
    double dt = 0.0, assembly = 0.0, preconditioner = 0.0, krylov = 0.0;
    for (unsigned int s = 0; s < n_steps; ++s)
    {
      dt = solver.next_time_step();
      solver.advance(dt);
      newton += solver.last_implicit_step().newton_iterations;
      linear += solver.last_implicit_step().linear_iterations;
      setups += solver.last_implicit_step().preconditioner_setups;
      assembly += solver.last_implicit_step().assembly_seconds;
      preconditioner += solver.last_implicit_step().preconditioner_seconds;
      krylov += solver.last_implicit_step().solve_seconds;
    }
    const double run = seconds_since(t1);
    if (root)
    {
      std::cout << (!implicit ? "explicit central difference"
                    : run_case.linear_solver == LinearSolverType::direct
                      ? "implicit Newmark, sparse LU"
                    : run_case.reuse_preconditioner
                      ? "implicit Newmark, multigrid reused"
                      : "implicit Newmark, multigrid rebuilt every solve")
                << ", " << omp_get_max_threads() << " thread(s): "
                << solver.n_active_cells() << " cells, " << solver.n_dofs() << " dofs, "
                << solver.n_quadrature_points() << " q-points, "
                << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " rank(s)\n"
                << "  setup " << setup << " s; " << n_steps << " steps of dt = " << dt << " s in "
                << run << " s = " << run / n_steps << " s/step\n";
      if (implicit)
        std::cout << "  Newton iterations/step " << double(newton) / n_steps
                  << ", linear iterations/Newton iteration "
                  << double(linear) / std::max(newton, 1u) << ", multigrid set-ups " << setups
                << "\n  per step: assembly " << assembly / n_steps << " s, multigrid set-up "
                << preconditioner / n_steps << " s, solve " << krylov / n_steps << " s\n";
      else
      {
        const FePhaseTimes& t = solver.explicit_phase_times();
        const double point_steps = solver.n_quadrature_points() * double(t.n_steps);
        std::cout << "  " << solver.n_quadrature_points() * double(n_steps) / run
                  << " quadrature-point updates per second (whole step); per phase: internal "
                     "forces (material update + assembly) "
                  << 1e9 * t.internal_forces / point_steps << " ns/point-step, the rest "
                  << 1e9 * t.rest / point_steps << " ns/point-step\n";
      }
    }
  }
  return 0;
}
