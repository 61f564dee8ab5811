// Pinocchio's side of benches/pinocchio/compare.py: builds the robot from the model file the
// script writes (joint placements and link inertias from robots/<name>.toml), then times
// crba + nonLinearEffects, aba and rnea, and computeRNEADerivatives and
// computeABADerivatives, over the states file, and prints a few results for the
// script to check against the project's.
//
// Usage: pinocchio_side MODEL STATES REPS
// Output lines: "time <function> <ns per call>", "value <function> <state> <numbers...>".
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/algorithm/rnea-derivatives.hpp>

namespace pin = pinocchio;

static pin::Model read_model(const char* path) {
  std::ifstream in(path);
  int n = 0;
  in >> n;
  pin::Model model;
  double g[3];
  in >> g[0] >> g[1] >> g[2];
  model.gravity.linear(Eigen::Vector3d(g[0], g[1], g[2]));
  pin::JointIndex parent = 0;
  for (int i = 0; i < n; ++i) {
    int kind = 0;
    Eigen::Vector3d axis;
    in >> kind >> axis[0] >> axis[1] >> axis[2];
    Eigen::Matrix3d r;
    Eigen::Vector3d p, com;
    for (int k = 0; k < 9; ++k) in >> r(k / 3, k % 3);
    in >> p[0] >> p[1] >> p[2];
    double mass = 0;
    in >> mass >> com[0] >> com[1] >> com[2];
    double ixx, ixy, ixz, iyy, iyz, izz;
    in >> ixx >> ixy >> ixz >> iyy >> iyz >> izz;
    Eigen::Matrix3d inertia;
    inertia << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
    const pin::SE3 placement(r, p);
    const std::string name = "joint" + std::to_string(i + 1);
    pin::JointIndex id = 0;
    switch (kind) {
      case 0: id = model.addJoint(parent, pin::JointModelRX(), placement, name); break;
      case 1: id = model.addJoint(parent, pin::JointModelRY(), placement, name); break;
      case 2: id = model.addJoint(parent, pin::JointModelRZ(), placement, name); break;
      case 3: id = model.addJoint(parent, pin::JointModelPX(), placement, name); break;
      case 4: id = model.addJoint(parent, pin::JointModelPY(), placement, name); break;
      case 5: id = model.addJoint(parent, pin::JointModelPZ(), placement, name); break;
      case 6: id = model.addJoint(parent, pin::JointModelRevoluteUnaligned(axis), placement, name); break;
      case 7: id = model.addJoint(parent, pin::JointModelPrismaticUnaligned(axis), placement, name); break;
      default: std::cerr << "unknown joint kind " << kind << "\n"; std::exit(2);
    }
    model.appendBodyToJoint(id, pin::Inertia(mass, com, inertia), pin::SE3::Identity());
    parent = id;
  }
  if (!in) {
    std::cerr << "cannot read the model file " << path << "\n";
    std::exit(2);
  }
  return model;
}

template <class F>
static double time_ns(int reps, int states, F f) {
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r)
    for (int s = 0; s < states; ++s) f(s);
  const auto end = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::nano>(end - start).count() / (double(reps) * states);
}

static void print(const char* name, int s, const Eigen::MatrixXd& m) {
  std::printf("value %s %d", name, s);
  for (Eigen::Index i = 0; i < m.size(); ++i) std::printf(" %.17g", m.data()[i]);
  std::printf("\n");
}

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: pinocchio_side MODEL STATES REPS\n";
    return 2;
  }
  const pin::Model model = read_model(argv[1]);
  pin::Data data(model);
  const int n = model.nq;
  std::ifstream in(argv[2]);
  int count = 0;
  in >> count;
  // Per state: q, qd, and a third vector used as tau (aba) and as qdd (rnea).
  std::vector<Eigen::VectorXd> q(count, Eigen::VectorXd(n)), v(count, Eigen::VectorXd(n)),
      u(count, Eigen::VectorXd(n));
  for (int s = 0; s < count; ++s) {
    for (int i = 0; i < n; ++i) in >> q[s][i];
    for (int i = 0; i < n; ++i) in >> v[s][i];
    for (int i = 0; i < n; ++i) in >> u[s][i];
  }
  const int reps = std::atoi(argv[3]);
  const double mcg = time_ns(reps, count, [&](int s) {
    pin::crba(model, data, q[s]);
    pin::nonLinearEffects(model, data, q[s], v[s]);
  });
  const double fd = time_ns(reps, count, [&](int s) { pin::aba(model, data, q[s], v[s], u[s]); });
  const double id = time_ns(reps, count, [&](int s) { pin::rnea(model, data, q[s], v[s], u[s]); });
  const double did = time_ns(reps, count, [&](int s) {
    pin::computeRNEADerivatives(model, data, q[s], v[s], u[s]);
  });
  const double dfd = time_ns(reps, count, [&](int s) {
    pin::computeABADerivatives(model, data, q[s], v[s], u[s]);
  });
  std::printf("time mcg %.3f\ntime fd %.3f\ntime id %.3f\n", mcg, fd, id);
  std::printf("time did %.3f\ntime dfd %.3f\n", did, dfd);
  for (int s = 0; s < 3 && s < count; ++s) {
    pin::crba(model, data, q[s]);
    data.M.triangularView<Eigen::StrictlyLower>() = data.M.transpose().triangularView<Eigen::StrictlyLower>();
    print("mass_matrix", s, data.M);
    print("bias", s, pin::nonLinearEffects(model, data, q[s], v[s]));
    print("forward_dynamics", s, pin::aba(model, data, q[s], v[s], u[s]));
    print("inverse_dynamics", s, pin::rnea(model, data, q[s], v[s], u[s]));
    // Row-major [d/dq | d/dqd] (n x 2n), as the generated functions return them.
    pin::computeRNEADerivatives(model, data, q[s], v[s], u[s]);
    Eigen::MatrixXd d(n, 2 * n);
    d << data.dtau_dq, data.dtau_dv;
    print("inverse_dynamics_derivatives", s, Eigen::MatrixXd(d.transpose()));
    pin::computeABADerivatives(model, data, q[s], v[s], u[s]);
    d << data.ddq_dq, data.ddq_dv;
    print("forward_dynamics_derivatives", s, Eigen::MatrixXd(d.transpose()));
  }
  return 0;
}
