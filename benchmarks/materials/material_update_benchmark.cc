// Throughput of the material point updates: nanoseconds per update_block point for each
// registered model, with and without failure, isotropic versus anisotropic tissue, plus the
// consistent tangent. Usage: material_update_benchmark [n_points] (default 1e6).
#include "materials/material_registry.h"

#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace vulnus::materials;

namespace
{
struct Block
{
  std::vector<Tensor2> F;
  std::vector<Eigen::Vector3f> a0; ///< as MPM points store them
  std::vector<std::uint8_t> failure;
  std::vector<PlasticHistory> plastic;
  std::vector<PlasticSlot> slots;
  std::vector<PointResponse> responses;
};

/// F = I + amplitude * U(-1, 1) per entry: near identity, fibers in compression and toe.
Block make_block(const std::size_t n, const double amplitude)
{
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  Block b;
  b.F.resize(n);
  b.a0.resize(n);
  b.failure.resize(n);
  b.plastic.resize(n);
  b.slots.resize(n);
  b.responses.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 9; ++k)
      b.F[i](k / 3, k % 3) = (k % 4 == 0 ? 1.0 : 0.0) + amplitude * uniform(rng);
    b.a0[i] = Vector3(normal(rng), normal(rng), normal(rng)).normalized().cast<float>();
    b.slots[i].index = static_cast<std::uint32_t>(i);
  }
  return b;
}

/// Best of `repeats` timings of one update_block over the block, in ns per point.
double time_updates(const Material& material, Block& b, const int repeats)
{
  double best = 1e300;
  for (int r = 0; r < repeats; ++r)
  {
    std::fill(b.failure.begin(), b.failure.end(), std::uint8_t(intact));
    std::fill(b.plastic.begin(), b.plastic.end(), PlasticHistory());
    const bool plastic = material.has_plastic_history();
    const PointBlock block{b.F.size(),
                           b.F.data(),
                           b.a0.data(),
                           b.failure.data(),
                           plastic ? b.plastic.data() : nullptr,
                           plastic ? b.slots.data() : nullptr,
                           b.responses.data()};
    const auto start = std::chrono::steady_clock::now();
    material.update_block(block);
    const auto stop = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::nano>(stop - start).count() /
                              static_cast<double>(b.F.size()));
  }
  return best;
}

double time_tangents(const Material& material, const Block& b, const std::size_t n)
{
  double checksum = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < n; ++i)
    checksum += material.tangent(b.F[i], b.a0[i].cast<double>(), PointState())(0, 0);
  const auto stop = std::chrono::steady_clock::now();
  if (checksum == 12345.678)
    std::printf(" ");
  return std::chrono::duration<double, std::nano>(stop - start).count() / static_cast<double>(n);
}
} // namespace

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  const int repeats = 5;
  Block tissue_block = make_block(n, 0.05);
  Block strained_block = make_block(n, 0.3); // many points fail, eigenvalues often needed
  Block bullet_block = make_block(n, 0.005); // elastic and plastic points (yield strain 3e-3)

  struct Case
  {
    std::string label;
    std::string model;
    bool with_fibers;
    bool failure;
    bool strained = false;
  };
  const std::vector<Case> cases = {
      {"tissue, anisotropic, failure on ", "transversely isotropic hyperelastic", true, true},
      {"tissue, anisotropic, failure off", "transversely isotropic hyperelastic", true, false},
      {"tissue, anisotropic, failing (0.3)", "transversely isotropic hyperelastic", true, true,
       true},
      {"tissue, isotropic,   failure on ", "isotropic hyperelastic", false, true},
      {"tissue, isotropic,   failure off", "isotropic hyperelastic", false, false},
      {"elastic plastic bullet          ", "elastic plastic", false, false},
      {"rigid                           ", "rigid", false, false}};

  std::printf("material update benchmark: %zu points per block, best of %d, one thread\n", n,
              repeats);
  std::printf("%-34s %12s %14s\n", "model", "ns/update", "ns/tangent");
  for (const Case& c : cases)
  {
    MaterialParameters parameters;
    parameters.model = c.model;
    parameters.tissue.with_fibers = c.with_fibers;
    parameters.tissue.failure.enabled = c.failure;
    const auto material = create_material(parameters);
    Block& block = c.model == "elastic plastic" ? bullet_block
                   : c.strained                 ? strained_block
                                                : tissue_block;
    const double update_ns = time_updates(*material, block, repeats);
    const double tangent_ns = time_tangents(*material, block, std::min<std::size_t>(n, 100000));
    std::size_t n_plastic = 0, n_failed = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      n_plastic += block.plastic[i].equivalent_plastic_strain > 0.0;
      n_failed += block.failure[i] != 0;
    }
    std::printf("%-34s %12.1f %14.1f   (plastic %zu, failed %zu)\n", c.label.c_str(), update_ns,
                tangent_ns, n_plastic, n_failed);
  }
  return 0;
}
