// HDF5 + XDMF output of the far field through DataOut: displacement and velocity (nodal),
// Cauchy stress, failure flag and MPI rank (per cell); one XDMF time series fe_mesh.xdmf.
#include "fem/far_field_data.h"

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_out.h>

#include <cstdio>
#include <filesystem>

namespace vulnus::fem
{
using namespace dealii;

void FarFieldSolver::write_output(const std::string& directory)
{
  Data& d = *data;
  if (Utilities::MPI::this_mpi_process(d.comm) == 0)
    std::filesystem::create_directories(directory);
  MPI_Barrier(d.comm);

  Data::Vector u(d.ghosted), v(d.ghosted);
  u = d.displacement;
  v = d.velocity;
  DataOut<3> data_out;
  data_out.attach_dof_handler(d.dof_handler);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      3, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(u, std::vector<std::string>(3, "displacement"),
                           DataOut<3>::type_dof_data, vector_field);
  data_out.add_data_vector(v, std::vector<std::string>(3, "velocity"), DataOut<3>::type_dof_data,
                           vector_field);

  const unsigned int n_cells = d.triangulation.n_active_cells();
  const char* const names[6] = {"stress_xx", "stress_yy", "stress_zz",
                                "stress_xy", "stress_yz", "stress_xz"};
  const unsigned int index[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
  std::vector<dealii::Vector<float>> stress(6, dealii::Vector<float>(n_cells));
  dealii::Vector<float> failure(n_cells), rank(n_cells);
  const float this_rank = Utilities::MPI::this_mpi_process(d.comm);
  for (const auto& cell : d.triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      const unsigned int k = cell->active_cell_index();
      for (unsigned int s = 0; s < 6; ++s)
        stress[s][k] = d.cell_stress[k][index[s][0]][index[s][1]];
      failure[k] = d.cell_failure[k];
      rank[k] = this_rank;
    }
  for (unsigned int s = 0; s < 6; ++s)
    data_out.add_data_vector(stress[s], names[s], DataOut<3>::type_cell_data);
  data_out.add_data_vector(failure, "failure", DataOut<3>::type_cell_data);
  data_out.add_data_vector(rank, "rank", DataOut<3>::type_cell_data);
  data_out.build_patches(d.mapping, d.prm.degree);

  DataOutBase::DataOutFilter filter(DataOutBase::DataOutFilterFlags(false, true));
  data_out.write_filtered_data(filter);
  char name[64];
  std::snprintf(name, sizeof(name), "fe_mesh_%05u.h5", d.n_outputs);
  data_out.write_hdf5_parallel(filter, directory + "/" + name, d.comm);
  d.xdmf_entries.push_back(data_out.create_xdmf_entry(filter, name, d.time, d.comm));
  data_out.write_xdmf_file(d.xdmf_entries, directory + "/fe_mesh.xdmf", d.comm);
  ++d.n_outputs;
}
} // namespace vulnus::fem
