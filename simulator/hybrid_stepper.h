// The hybrid stepper: the MPM zone and the FE far field of coupling::HybridSolver. Under
// mpirun every rank runs it (the zone in slabs, the far field in deal.II's partition).
#pragma once

#include "coupling/hybrid_solver.h"
#include "deck/run_parameters.h"
#include "simulator/hybrid_monitors.h"
#include "simulator/mpm_stepper.h"
#include "simulator/stepper.h"

namespace vulnus::simulator
{
class HybridStepper : public Stepper
{
public:
  HybridStepper(const deck::RunParameters& parameters, MPI_Comm communicator);

  const char* method() const override { return "hybrid"; }
  void log_scene(io::RunDirectory& directory) const override;
  void advance() override { solver.advance(); }
  bool finished() const override { return solver.finished(); }
  double time() const override { return solver.time(); }
  double end_time() const override { return solver.mpm().scene().end_time; }
  double expected_end_time() const override { return solver.mpm().expected_end_time(); }
  std::uint64_t step_count() const override { return solver.mpm().step_count(); }
  double last_time_step() const override { return solver.mpm().last_time_step(); }
  std::string progress() const override;
  MPI_Comm communicator() const override { return solver.mpm().rank_group().communicator(); }
  std::string blow_up_remedy() const override;
  std::vector<std::string> events() override;
  double energy_balance_error() const override;
  std::string energy_error_causes() const override;
  std::vector<std::string> check_validity(bool final_check) override;

  std::vector<std::string> history_columns() const override;
  std::vector<double> history_row() const override;
  std::vector<std::string> final_warnings() const override;
  nlohmann::json summary(const analysis::RunTotals& totals) const override;
  std::string final_report(const nlohmann::json& summary) const override;

  const mpm::Solver* mpm_side() const override { return &solver.mpm(); }
  fem::FarFieldSolver* fe_side() override { return &solver.fe(); }
  std::int32_t fe_material_id() const override
  {
    return static_cast<std::int32_t>(solver.scene().coupled_body);
  }

  bool can_checkpoint() const override { return true; }
  void save(std::ostream& out) const override
  {
    solver.save(out);
    monitors.save(out);
  }
  void restore(std::istream& in) override
  {
    solver.restore(in);
    monitors.restore(in);
    conversions_logged = solver.conversions().size();
    hold_release_reported = solver.mpm().projectile_hold().record().release_step >= 0;
    rotation_reported = solver.mpm().projectile_rotation().exceeded_step() >= 0;
  }

private:
  coupling::HybridSolver solver;
  std::size_t conversions_logged = 0;
  bool hold_release_reported = false;
  bool rotation_reported = false;
  ProjectileStart projectile;
  double initial_energy; ///< J, of the whole scene at t = 0
  Eigen::Vector3d initial_momentum; ///< kg m/s, of the whole scene at t = 0
  HybridMonitors monitors;
};
} // namespace vulnus::simulator
