// The wall of rigid blocks through vuinteraction_ (issue 12, item 3): each
// check against a value computed without the scene solver.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "input/scene_file.hpp"
#include "scenes/wall.hpp"
#include "solvers/block_solver.hpp"
#include "wall_statics.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::test;

namespace {

std::string data(const char* name) { return std::string(MJ_TEST_DATA_DIR) + "/" + name; }

struct Run {
  WallRunSummary summary;
  std::vector<WallSample> samples;
};

Run run(const SceneSpec& spec, BlockSolverOptions options = {}, int every = 1) {
  const WallModel model = build_wall(spec.wall);
  BlockSolver solver(spec, model, options);
  Run r;
  r.summary = solver.run(every, [&](const WallSample& s) { r.samples.push_back(s); }, nullptr, nullptr);
  return r;
}

// The closed-form peak shear strength at sigma_n < 0 (docs/model.md 4).
double peak_shear_strength(const Parameters& p, double sigma_n) {
  const double deg = 3.14159265358979323846 / 180, tan_phi = std::tan(p.phi0 * deg);
  const double C = p.c0 * p.c0 / p.ft0;
  const double alpha = 0.5 * (C / tan_phi - p.ft0 * tan_phi), beta = 0.5 * (C / tan_phi + p.ft0 * tan_phi);
  return std::sqrt((beta - sigma_n * tan_phi) * (beta - sigma_n * tan_phi) - alpha * alpha);
}

double relative(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

}  // namespace

TEST_CASE("wall: one block under precompression pushed sideways: peak and residual of the closed form",
          "[wall]") {
  const SceneSpec spec = read_scene_file(data("wall_one_block.toml"));
  const WallModel m = build_wall(spec.wall);
  REQUIRE(m.blocks() == 0);  // the unit is clamped in the beam: one joint, beam on base
  const double area = m.length * spec.wall.unit_depth;
  const double N = base_load(spec);
  const Parameters& p = spec.joint.values;
  const Run r = run(spec);
  const double peak = area * peak_shear_strength(p, -N / area);
  const double residual = N * std::tan(p.phir * 3.14159265358979323846 / 180);
  INFO("peak " << r.summary.peak_shear << " N, closed form " << peak << " N; end " << r.samples.back().base_shear
               << " N, N tan(phir) " << residual << " N");
  CHECK(relative(r.summary.peak_shear, peak) < 0.01);
  CHECK(relative(r.samples.back().base_shear, residual) < 0.01);
}

TEST_CASE("wall: a slender panel rocks at the threshold of statics", "[wall]") {
  const SceneSpec spec = read_scene_file(data("wall_rocking.toml"));
  const WallModel m = build_wall(spec.wall);
  // Every vertical load passes through the body's centroid (mid-length); the
  // actuator pushes at the centroid's height above the base joint.
  const double N = base_load(spec);
  const double lever = m.bodies[m.beam()].cy;
  const double threshold = N * 0.5 * m.length / lever;
  const Run r = run(spec);
  INFO("peak " << r.summary.peak_shear << " N, statics " << threshold << " N, top rotation "
               << r.samples.back().top_rotation);
  CHECK(relative(r.summary.peak_shear, threshold) < 0.02);
  CHECK(r.samples.back().top_rotation < -1e-3);  // it did rock (clockwise)
}

TEST_CASE("wall: the energy balance closes within 1 % over a cracking run", "[wall]") {
  const SceneSpec spec = read_scene_file(data("wall_small.toml"));
  const Run r = run(spec, {}, 50);
  const WallEnergies& e = r.samples.back().energy;
  INFO("external " << e.external << ", elastic " << e.elastic << ", dissipated " << e.dissipated << ", kinetic "
                   << e.kinetic << ", damping " << e.damping << ", balance " << e.balance());
  CHECK(e.dissipated > 0.2 * e.external);  // it cracked
  CHECK(std::fabs(e.balance()) < 0.01 * e.external);
}

TEST_CASE("wall: quasi-static: the peak hardly moves with the loading rate or the time increment", "[wall]") {
  SceneSpec spec = read_scene_file(data("wall_one_block.toml"));
  const double peak = run(spec).summary.peak_shear;
  SceneSpec slower = spec;
  slower.loading.velocity *= 0.5;
  const double peak_slower = run(slower).summary.peak_shear;
  SceneSpec finer = spec;
  finer.solver.safety_factor *= 0.5;
  const double peak_finer = run(finer).summary.peak_shear;
  INFO("peak " << peak << " N, at half the rate " << peak_slower << " N, at half the increment " << peak_finer);
  CHECK(relative(peak_slower, peak) < 0.02);
  CHECK(relative(peak_finer, peak) < 0.01);
}

TEST_CASE("wall: nBlock 1, 7, 64, 136 and 1, 2 or 3 threads give bit-identical results", "[wall]") {
  const SceneSpec spec = read_scene_file(data("wall_small.toml"));
  auto history = [&](int block, int threads) {
    BlockSolverOptions o;
    o.block = block, o.threads = threads, o.max_increments = 4000;
    return run(spec, o, 20).samples;
  };
  const std::vector<WallSample> reference = history(136, 1);
  REQUIRE(build_wall(spec.wall).points.size() > 64);  // 64 splits the points into two blocks
  for (auto [block, threads] : {std::pair{1, 1}, {7, 1}, {64, 1}, {64, 2}, {136, 2}, {1, 2}, {7, 2}, {7, 3}, {136, 3}}) {
    const std::vector<WallSample> h = history(block, threads);
    REQUIRE(h.size() == reference.size());
    bool same = true;
    for (size_t i = 0; i < h.size(); ++i) {
      const WallSample &a = h[i], &b = reference[i];
      const WallEnergies &ea = a.energy, &eb = b.energy;
      same = same && a.increment == b.increment && a.time == b.time && a.stage == b.stage && a.top_ux == b.top_ux &&
             a.top_uy == b.top_uy && a.top_rotation == b.top_rotation && a.base_shear == b.base_shear &&
             a.base_normal == b.base_normal && a.actuator == b.actuator && ea.external == eb.external &&
             ea.elastic == eb.elastic && ea.dissipated == eb.dissipated && ea.plastic == eb.plastic &&
             ea.damage == eb.damage && ea.unilateral == eb.unilateral && ea.kinetic == eb.kinetic &&
             ea.damping == eb.damping;
    }
    INFO("nBlock " << block << ", threads " << threads);
    CHECK(same);
  }
}
