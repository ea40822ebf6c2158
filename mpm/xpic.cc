// XPIC(m)'s grid passes: the points' masses times a nodal field read at the points, scattered
// back, and the series' terms built from it.
#include "mpm/xpic.h"

#include "mpm/point_shares.h"
#include "mpm/stencil.h"

#include <array>

namespace vulnus::mpm
{
namespace
{
template <ShapeFunction shape>
void scatter_share(const Grid& grid, const double lp, const std::size_t b, const ShareRange range,
                   const Particles& particles, const Vector3* nodal, Vector3* direct,
                   Vector3* contested)
{
  constexpr int n_entries = stencil_entries(shape);
  const std::size_t n_bodies = particles.n_bodies();
  std::array<std::int32_t, n_entries> slots;
  std::array<double, n_entries> weights;
  for (long p = range.begin; p < range.end; ++p)
  {
    Vector3 value = Vector3::Zero();
    int n_nodes = 0;
    for_each_node<shape>(grid, lp, particles.position[p], particles.deformation_gradient[p],
                         [&](const std::int64_t key, const double w, const Vector3&)
                         {
                           const std::int32_t slot = grid.slot(key);
                           value += w * nodal[slot * n_bodies + b];
                           slots[n_nodes] = slot;
                           weights[n_nodes++] = w;
                         });
    const Vector3 m_value = particles.mass[p] * value;
    for (int i = 0; i < n_nodes; ++i)
      scatter_target(grid, slots[i], n_bodies, b, direct, contested) += weights[i] * m_value;
  }
}

bool deformable_with_mass(const GridUpdateSettings& settings, const GridFields& fields,
                          const std::size_t e, const std::size_t b)
{
  return !settings.body_is_rigid[b] && fields.data[e].mass > settings.mass_tolerance;
}
} // namespace

void scatter_point_values(const Grid& grid, const TransferSettings& transfer,
                          const KinematicsSettings& kinematics, const Particles& particles,
                          const std::vector<Vector3>& nodal, std::vector<Vector3>& scattered,
                          std::vector<std::vector<Vector3>>& per_share)
{
  scattered.resize(nodal.size());
  with_shape(transfer.shape,
             [&](auto shape_constant)
             {
               constexpr ShapeFunction shape = decltype(shape_constant)::value;
               scatter_by_shares(grid, particles, Vector3::Zero().eval(), scattered, per_share,
                                 [&](int, const std::size_t b, const ShareRange range,
                                     Vector3* direct, Vector3* contested)
                                 {
                                   if (kinematics.body_is_rigid[b] || kinematics.skips(b))
                                     return;
                                   scatter_share<shape>(grid, transfer.half_size_cells[b], b,
                                                        range, particles, nodal.data(), direct,
                                                        contested);
                                 });
             });
}

void first_xpic_term(const Grid& grid, const GridUpdateSettings& settings, const GridFields& fields,
                     const std::vector<Vector3>& start, std::vector<Vector3>& term)
{
  const std::size_t n_bodies = fields.n_bodies;
  const long n_nodes = static_cast<long>(grid.n_active());
  term.resize(fields.velocity.size());
#pragma omp parallel for schedule(static)
  for (long node = 0; node < n_nodes; ++node)
    for (std::size_t b = 0; b < n_bodies; ++b)
    {
      const std::size_t e = node * n_bodies + b;
      term[e] = deformable_with_mass(settings, fields, e, b) ? start[e] : Vector3::Zero();
    }
}

void next_xpic_term(const Grid& grid, const GridUpdateSettings& settings, const GridFields& fields,
                    const std::vector<Vector3>& scattered, std::vector<Vector3>& term,
                    std::vector<Vector3>& correction, std::array<Vector3, 6>& support_impulse)
{
  const std::size_t n_bodies = fields.n_bodies;
  const long n_nodes = static_cast<long>(grid.n_active());
  const bool supports = any_support(settings.faces);
#pragma omp parallel
  {
    std::array<Vector3, 6> impulse;
    impulse.fill(Vector3::Zero());
#pragma omp for schedule(static)
    for (long node = 0; node < n_nodes; ++node)
    {
      const std::int64_t key = grid.active_keys()[node];
      for (std::size_t b = 0; b < n_bodies; ++b)
      {
        const std::size_t e = node * n_bodies + b;
        if (!deformable_with_mass(settings, fields, e, b))
        {
          term[e].setZero();
          continue;
        }
        term[e] -= scattered[e] / fields.data[e].mass;
        if (supports && (!settings.owns_node || settings.owns_node(key)))
          apply_face_conditions(grid, settings.faces, key, fields.data[e].mass, term[e], impulse);
        else if (supports) // booked by the rank that owns the node
          apply_face_conditions(grid, settings.faces, key, term[e]);
        correction[e] += term[e];
      }
    }
#pragma omp critical(vulnus_series_supports)
    for (int f = 0; f < 6; ++f)
      support_impulse[f] += impulse[f];
  }
}
} // namespace vulnus::mpm
