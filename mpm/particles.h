// Material points stored as arrays (structure of arrays). Points of one body are kept
// contiguous (body_begin) so material updates dispatch once per body; within a body they are
// sorted by grid cell now and then for cache locality. Plastic histories (56 B) exist only for
// the points of elastic-plastic bodies, in a pool the points refer to by slot.
#pragma once

#include "materials/material.h"

#include <Eigen/Core>

#include <algorithm>
#include <tuple>
#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
using Vector3 = Eigen::Vector3d;
using Vector3f = Eigen::Vector3f;
using Tensor2 = Eigen::Matrix3d;
/// A symmetric tensor in Voigt order xx yy zz xy yz xz (48 bytes instead of 72).
using SymmetricTensor = Eigen::Matrix<double, 6, 1>;

inline SymmetricTensor symmetric_part(const Tensor2& t)
{
  SymmetricTensor s;
  s << t(0, 0), t(1, 1), t(2, 2), 0.5 * (t(0, 1) + t(1, 0)), 0.5 * (t(1, 2) + t(2, 1)),
    0.5 * (t(0, 2) + t(2, 0));
  return s;
}

inline Tensor2 full_tensor(const SymmetricTensor& s)
{
  Tensor2 t;
  t << s[0], s[3], s[5], //
    s[3], s[1], s[4],    //
    s[5], s[4], s[2];
  return t;
}

struct Particles
{
  std::vector<Vector3> position;
  /// Where the point started (wound maps); single precision, 3 nm at 5 cm.
  std::vector<Vector3f> reference_position;
  std::vector<Vector3> velocity;
  /// APIC affine velocity C_p (the grid velocity gradient at the point, 1/s); zero for
  /// the other transfers. Single precision: it only shapes the momentum a point lends nodes.
  std::vector<Eigen::Matrix3f> affine_velocity;
  std::vector<Tensor2> deformation_gradient;
  std::vector<SymmetricTensor> stress; ///< Cauchy stress, Pa
  std::vector<double> mass;
  std::vector<double> reference_volume;
  /// Reference unit fiber a0 (bodies with fibers); single precision, normalized when used.
  std::vector<Vector3f> fiber_direction;
  std::vector<std::uint8_t> failure; ///< materials::FailureFlag bits
  /// Where the point's plastic history is in plastic_pool (none for laws without one).
  std::vector<materials::PlasticSlot> plastic_slot;
  std::vector<double> energy_density;      ///< J per reference m^3, unfailed parts
  std::vector<double> dissipated_density;  ///< accumulated J per reference m^3
  std::vector<double> wave_speed;          ///< m/s, from the last stress update
  std::vector<std::uint32_t> id;           ///< stable identifier, survives sorting
  /// Half-edge vectors of the point's domain, m, as columns: a cube of the point's volume at
  /// seeding, moved with each step's velocity gradient since (debris included), halved along
  /// the edge a split cuts (mpm/point_splitting.h). Single precision: it only decides splits.
  std::vector<Eigen::Matrix3f> domain;
  /// Not per point: the histories plastic_slot refers to, in no particular order; entries of
  /// points that left stay until the next compaction (permute, keep_only).
  std::vector<materials::PlasticHistory> plastic_pool;

  /// Body b owns the index range [body_begin[b], body_begin[b+1]).
  std::vector<std::size_t> body_begin{0};

  std::size_t size() const { return position.size(); }
  std::size_t n_bodies() const { return body_begin.size() - 1; }
  std::size_t begin_of(std::size_t b) const { return body_begin[b]; }
  std::size_t end_of(std::size_t b) const { return body_begin[b + 1]; }
  /// The body point i belongs to.
  std::size_t body_of(std::size_t i) const
  {
    return static_cast<std::size_t>(
             std::upper_bound(body_begin.begin() + 1, body_begin.end(), i) - body_begin.begin()) -
           1;
  }

  /// Room for n points, n_plastic of them with a plastic history.
  void reserve(std::size_t n, std::size_t n_plastic = 0);
  /// Appends one point to the last body (call start_body first), with a fresh plastic
  /// history when plastic_history is set.
  void append(const Vector3& x, const Vector3& v, double m, double volume,
              const Vector3& fiber, bool plastic_history = false);
  /// The plastic history of point p, or null.
  materials::PlasticHistory* plastic_of(std::size_t p)
  {
    const std::uint32_t slot = plastic_slot[p].index;
    return slot == materials::PlasticSlot::none ? nullptr : &plastic_pool[slot];
  }
  const materials::PlasticHistory* plastic_of(std::size_t p) const
  {
    return const_cast<Particles&>(*this).plastic_of(p);
  }
  /// Rebuilds plastic_pool in point order without the entries no point refers to.
  void compact_plastic_pool();
  /// The first body with a point whose slot lies outside plastic_pool or (given a flag per
  /// body) whose slot's presence disagrees with its body's flag; -1 when there is none.
  long body_with_invalid_plastic_slots(
    const std::vector<char>* body_has_plastic_history = nullptr) const;
  /// Opens a new body; points appended from now on belong to it.
  void start_body() { body_begin.push_back(size()); }
  /// Closes the last body (records its end).
  void finish_body() { body_begin.back() = size(); }

  /// Points [begin, end) as a one-body container (with their plastic histories).
  Particles copy_of_range(std::size_t begin, std::size_t end) const;
  /// The points of body b alone, as a one-body container.
  Particles copy_of_body(std::size_t b) const { return copy_of_range(begin_of(b), end_of(b)); }
  /// Writes `part` (a copy_of_body(b) advanced since, same points in the same order) back
  /// into body b.
  void write_back_body(std::size_t b, const Particles& part);

  /// Inserts the points of `added` (a one-body container) at the end of body b, with their
  /// plastic histories; later bodies move up.
  void insert_into_body(std::size_t b, const Particles& added);

  /// Removes the points whose keep flag is 0, preserving order and body ranges (and compacts
  /// the plastic pool).
  void keep_only(const std::vector<char>& keep);

  /// Reorders every array by `order` (new index i takes old index order[i]) in place: 1 byte
  /// of scratch per point instead of a copy of the largest array. Compacts the plastic pool
  /// into the new point order.
  void permute(const std::vector<std::uint32_t>& order);

  /// Calls f on each per-point array (not body_begin, not plastic_pool), always in the same
  /// order.
  template <class F>
  void for_each_array(F&& f)
  {
    std::apply([&](auto... member) { (f(this->*member), ...); }, arrays());
  }
  template <class F>
  void for_each_array(F&& f) const
  {
    std::apply([&](auto... member) { (f(this->*member), ...); }, arrays());
  }
  /// Calls f(mine, theirs) on each per-point array and the same array of `other`.
  template <class F>
  void for_each_array_with(const Particles& other, F&& f)
  {
    std::apply([&](auto... member) { (f(this->*member, other.*member), ...); }, arrays());
  }

private:
  static constexpr auto arrays()
  {
    return std::make_tuple(&Particles::position, &Particles::reference_position,
                           &Particles::velocity, &Particles::affine_velocity,
                           &Particles::deformation_gradient, &Particles::stress, &Particles::mass,
                           &Particles::reference_volume, &Particles::fiber_direction,
                           &Particles::failure, &Particles::plastic_slot,
                           &Particles::energy_density, &Particles::dissipated_density,
                           &Particles::wave_speed, &Particles::id, &Particles::domain);
  }
};
} // namespace vulnus::mpm
