#include "output/scene_csv.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "input/input_error.hpp"
#include "output/output_paths.hpp"

namespace mortar::harness {

namespace {

std::ofstream open_for_writing(const std::string& path) {
  std::ofstream f(path);
  if (!f) throw InputError(cannot_write(path));
  f.precision(10);
  return f;
}

// Displacement of the material point (x, y) of body `b` under q (small rotation).
void displacement(const Body& b, const double* q, double x, double y, double& ux, double& uy) {
  ux = q[0] - q[2] * (y - b.cy);
  uy = q[1] + q[2] * (x - b.cx);
}

}  // namespace

struct HistoryCsv::Impl {
  std::ofstream f;
};

HistoryCsv::HistoryCsv(const std::string& path) : impl_(new Impl{open_for_writing(path)}) {
  impl_->f << "increment,time,stage,top_ux,top_uy,top_rotation,base_shear,base_normal,top_normal,actuator,"
              "external_work,elastic_energy,dissipation,plastic_dissipation,damage_dissipation,unilateral_energy,"
              "kinetic_energy,damping_work,energy_accounted,balance_error,kinetic_to_internal\n";
}

HistoryCsv::~HistoryCsv() { delete impl_; }

void HistoryCsv::row(const WallSample& s) {
  const WallEnergies& e = s.energy;
  impl_->f << s.increment << ',' << s.time << ',' << s.stage << ',' << s.top_ux << ',' << s.top_uy << ','
           << s.top_rotation << ',' << s.base_shear << ',' << s.base_normal << ',' << s.top_normal << ',' << s.actuator << ',' << e.external
           << ',' << e.elastic << ',' << e.dissipated << ',' << e.plastic << ',' << e.damage << ',' << e.unilateral
           << ',' << e.kinetic << ',' << e.damping << ',' << e.accounted() << ',' << e.balance() << ','
           << (e.internal() > 0 ? e.kinetic / e.internal() : 0.0) << '\n';
}

Magnification picture_magnification(const SceneOutputSpec& output, const WallModel& m, const WallSnapshot& s) {
  Magnification mag;
  for (const ContactPoint& p : m.points) {
    // The two bodies' displacements at the point: equal under a rigid motion.
    double ax, ay, bx, by;
    displacement(m.bodies[p.a], &s.q[3 * p.a], p.x, p.y, ax, ay);
    displacement(m.bodies[p.b], &s.q[3 * p.b], p.x, p.y, bx, by);
    mag.largest_relative = std::max(mag.largest_relative, std::hypot(bx - ax, by - ay));
  }
  if (output.magnification > 0) {
    mag.factor = output.magnification, mag.automatic = false;
  } else if (mag.largest_relative > 0) {
    mag.factor = 0.05 * m.height / mag.largest_relative;
  }
  return mag;
}

void write_snapshot_csv(const std::string& dir, int k, const WallModel& m, const WallSnapshot& s,
                        double magnification) {
  const std::string stem = dir + "/snapshot_" + std::to_string(k);
  std::ofstream b = open_for_writing(stem + "_blocks.csv");
  b << "x_mm,y_mm,body\n";
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& body = m.bodies[i];
    const double* q = &s.q[3 * i];
    const auto& c = body.corners;
    for (size_t j = 0; j <= c.size() / 2; ++j) {  // closed outline: the first corner again
      const double x = c[2 * (j % (c.size() / 2))], y = c[2 * (j % (c.size() / 2)) + 1];
      double ux, uy;
      displacement(body, q, x, y, ux, uy);
      b << x + magnification * ux << ',' << y + magnification * uy << ',' << i << '\n';
    }
    b << "\n";
  }
  std::ofstream j = open_for_writing(stem + "_joints.csv");
  j << "x_mm,y_mm,bed,opening_mm,slip_mm,d_n,d_s,dissipation_N_per_mm,kappa_c_mm,role\n";
  for (size_t i = 0; i < m.points.size(); ++i) {
    const ContactPoint& p = m.points[i];
    // Drawn at the mean displaced position of the two faces.
    double x = p.x, y = p.y;
    for (int body : {p.a, p.b}) {
      double ux, uy;
      displacement(m.bodies[body], &s.q[3 * body], p.x, p.y, ux, uy);
      x += 0.5 * magnification * ux;
      y += 0.5 * magnification * uy;
    }
    j << x << ',' << y << ',' << (p.bed ? 1 : 0) << ',' << s.opening[i] << ',' << s.slip[i] << ',' << s.damage_n[i]
      << ',' << s.damage_s[i] << ',' << s.dissipation[i] << ',' << s.kappa_c[i] << ',' << static_cast<int>(p.role)
      << '\n';
  }
}

std::string scene_summary(const SceneSpec& spec, const WallModel& m, const WallRunSummary& r,
                          const WallSample& last) {
  std::ostringstream o;
  o.precision(4);
  const WallEnergies& e = last.energy;
  const double balance = std::fabs(e.balance()) / std::max(1e-300, std::fabs(e.external));
  o << "scene: " << spec.file << "\n"
    << "wall: " << m.blocks() << " blocks, " << m.joint_faces << " joint faces, " << r.points
    << " contact points in " << r.blocks << " block(s) per increment\n"
    << "time increment: " << r.time_increment << " s = " << spec.solver.safety_factor << " x the stable bound "
    << r.stable_increment << " s (mass scaling " << spec.solver.mass_scaling << ", damping alpha "
    << spec.solver.mass_damping << " 1/s)\n"
    << "increments: " << r.increments << ", " << r.seconds << " s, " << r.point_updates_per_second() / 1e6
    << " million point-updates per second, " << 100 * r.seconds_in_routine / std::max(1e-300, r.seconds)
    << " % of the time inside vuinteraction_\n"
    << "peak base shear: " << r.peak_shear / 1000 << " kN at a top displacement of " << r.peak_displacement
    << " mm (t = " << r.peak_time << " s)\n"
    << "end: base shear " << last.base_shear / 1000 << " kN at " << last.top_ux << " mm\n"
    << "energy at the end [N mm]: external " << e.external << ", elastic " << e.elastic << ", dissipated "
    << e.dissipated << " (plastic " << e.plastic << ", damage " << e.damage << ", unilateral " << e.unilateral
    << "), kinetic " << e.kinetic << ", damping " << e.damping << "\n"
    << "energy balance error: " << balance << " of the external work at the end, at most " << r.max_balance_error
    << " of the largest external work so far in the displacement stage\n"
    << "kinetic / internal energy in the displacement stage: at most " << r.max_kinetic_ratio << "\n"
    << r.integration_flags << "\n" << (r.unpaired_warning.empty() ? "" : r.unpaired_warning + "\n");
  return o.str();
}

}  // namespace mortar::harness
