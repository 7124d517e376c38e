#include "output/scene_csv.hpp"

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

}  // namespace

struct HistoryCsv::Impl {
  std::ofstream f;
};

HistoryCsv::HistoryCsv(const std::string& path) : impl_(new Impl{open_for_writing(path)}) {
  impl_->f << "increment,time,stage,top_ux,top_uy,top_rotation,base_shear,base_normal,actuator,"
              "external_work,elastic_energy,dissipation,plastic_dissipation,damage_dissipation,unilateral_energy,"
              "kinetic_energy,damping_work,balance_error,kinetic_to_internal\n";
}

HistoryCsv::~HistoryCsv() { delete impl_; }

void HistoryCsv::row(const WallSample& s) {
  const WallEnergies& e = s.energy;
  impl_->f << s.increment << ',' << s.time << ',' << s.stage << ',' << s.top_ux << ',' << s.top_uy << ','
           << s.top_rotation << ',' << s.base_shear << ',' << s.base_normal << ',' << s.actuator << ',' << e.external
           << ',' << e.elastic << ',' << e.dissipated << ',' << e.plastic << ',' << e.damage << ',' << e.unilateral
           << ',' << e.kinetic << ',' << e.damping << ',' << e.balance() << ','
           << (e.internal() > 0 ? e.kinetic / e.internal() : 0.0) << '\n';
}

void write_snapshot_csv(const std::string& dir, int k, const WallModel& m, const WallSnapshot& s,
                        double magnification) {
  const std::string stem = dir + "/snapshot_" + std::to_string(k);
  std::ofstream b = open_for_writing(stem + "_blocks.csv");
  b << "x,y,body\n";
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& body = m.bodies[i];
    const double* q = &s.q[3 * i];
    const auto& c = body.corners;
    for (size_t j = 0; j <= c.size() / 2; ++j) {  // closed outline: the first corner again
      const double x = c[2 * (j % (c.size() / 2))], y = c[2 * (j % (c.size() / 2)) + 1];
      const double ux = q[0] - q[2] * (y - body.cy), uy = q[1] + q[2] * (x - body.cx);
      b << x + magnification * ux << ',' << y + magnification * uy << ',' << i << '\n';
    }
    b << "\n";
  }
  std::ofstream j = open_for_writing(stem + "_joints.csv");
  j << "x,y,bed,damage,opening\n";
  for (size_t i = 0; i < m.points.size(); ++i) {
    const ContactPoint& p = m.points[i];
    // Drawn at the mean displaced position of the two faces.
    double x = p.x, y = p.y;
    for (int body : {p.a, p.b}) {
      const Body& bd = m.bodies[body];
      const double* q = &s.q[3 * body];
      x += 0.5 * magnification * (q[0] - q[2] * (p.y - bd.cy));
      y += 0.5 * magnification * (q[1] + q[2] * (p.x - bd.cx));
    }
    j << x << ',' << y << ',' << (p.bed ? 1 : 0) << ',' << s.damage[i] << ',' << s.opening[i] << '\n';
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
