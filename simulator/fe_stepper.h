// The pure-FE stepper (Scene/Method = FE): the deal.II far-field solver on the one box body,
// with the deck's face supports and load, stepped to the end time at its own stable step.
#pragma once

#include "deck/run_parameters.h"
#include "fem/far_field_solver.h"
#include "simulator/stepper.h"

#include <Eigen/Core>

#include <memory>

namespace vulnus::simulator
{
class FeStepper : public Stepper
{
public:
  FeStepper(const deck::RunParameters& parameters, MPI_Comm communicator);

  const char* method() const override { return "FE"; }
  void log_scene(io::RunDirectory& directory) const override;
  void advance() override;
  bool finished() const override;
  double time() const override { return solver->time(); }
  double end_time() const override { return parameters.end_time; }
  std::uint64_t step_count() const override { return solver->step_number(); }
  double last_time_step() const override { return dt; }
  std::string progress() const override;
  MPI_Comm communicator() const override { return solver->communicator(); }
  std::string blow_up_remedy() const override;
  double energy_balance_error() const override;
  std::string energy_error_causes() const override;

  std::vector<std::string> history_columns() const override;
  std::vector<double> history_row() const override;
  std::vector<std::string> final_warnings() const override;
  nlohmann::json summary(const analysis::RunTotals& totals) const override;
  std::string final_report(const nlohmann::json& summary) const override;

  fem::FarFieldSolver* fe_side() override { return solver.get(); }

  bool can_checkpoint() const override { return true; }
  void save(std::ostream& out) const override { solver->save(out); }
  void restore(std::istream& in) override { solver->restore(in); }

private:
  fem::FeSceneParameters parameters;
  std::unique_ptr<fem::FarFieldSolver> solver;
  double dt = 0.0; ///< s, of the last step
  Eigen::Vector3d initial_momentum = Eigen::Vector3d::Zero(); ///< kg m/s, at t = 0
};
} // namespace vulnus::simulator
