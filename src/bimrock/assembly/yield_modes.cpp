#include <bimrock/assembly/yield_modes.hpp>

#include <cmath>

#include <bimrock/assembly/kinematics.hpp>

namespace bimrock {

LocalOperator local_operator(const Model& model, const YieldPoint& p) {
  LocalOperator op;
  op.blocks = {p.block_i, p.block_j};
  const Vec2& ci = model.blocks[p.block_i].centroid;
  if (p.is_block()) {
    op.e = Eigen::MatrixXd::Zero(3, 6);
    op.e.rightCols<3>().setIdentity();
  } else if (p.is_bolt()) {
    const BoltSpring& s = spring_of(model, p);
    op.e = bolt_B(s.axis, ci, s.a, model.blocks[p.block_j].centroid, s.b);
  } else if (p.block_j == kGround) {
    op.e = support_B(p.normal, ci, p.position);
  } else {
    op.e = interface_B(p.normal, ci, model.blocks[p.block_j].centroid, p.position);
  }
  return op;
}

Eigen::MatrixXd local_stiffness(const Model& model, const YieldPoint& p) {
  if (p.is_block())
    return elasticity_matrix(model.block_materials[p.material], model.settings.plane);
  if (p.is_bolt()) {
    const Bolt& bolt = bolt_of(model, p);
    return Eigen::Vector2d(bolt.axial_stiffness, bolt.shear_stiffness).asDiagonal();
  }
  const Interface& f = model.interfaces[p.owner];
  return Eigen::Vector2d(f.normal_stiffness, f.shear_stiffness).asDiagonal();
}

Eigen::VectorXd local_strain(const Model& model, const YieldPoint& p, const Eigen::VectorXd& u) {
  const LocalOperator op = local_operator(model, p);
  Eigen::VectorXd x(6 * op.n_blocks());
  for (int k = 0; k < op.n_blocks(); ++k)
    x.segment<6>(6 * k) = u.segment<6>(6 * op.blocks[k]);
  return op.e * x;
}

Eigen::VectorXd local_stress(const Model& model, const YieldPoint& p, const PlasticState& s,
                             const Eigen::VectorXd& u) {
  Eigen::VectorXd strain = local_strain(model, p, u);
  if (!p.is_block())
    strain -= s.installed_at;
  return p.initial.head(strain.size()) +
         local_stiffness(model, p) * (strain - s.plastic.head(strain.size()));
}

ModeKind mode_kind(const YieldPoint& p, int mode) {
  if (p.is_block())
    return ModeKind::block_facet;
  if (p.is_bolt())
    return mode == 0   ? ModeKind::bolt_tension
           : mode == 1 ? ModeKind::bolt_shear_positive
                       : ModeKind::bolt_shear_negative;
  return mode == 0   ? ModeKind::slip_positive
         : mode == 1 ? ModeKind::slip_negative
                     : ModeKind::opening;
}

Eigen::Vector3d joint_values(const JointStrength& law, const PlasticState& s, double sigma_n,
                             double tau) {
  const double tan_phi = law.friction.value(s.slip);
  const double c = law.cohesion.value(s.slip);
  const double sigma_t = law.tensile.value(s.max_gap);
  return {tau + sigma_n * tan_phi - c, -tau + sigma_n * tan_phi - c, sigma_n - sigma_t};
}

Eigen::VectorXd bolt_values(const Bolt& bolt, double axial, double shear) {
  if (!bolt.shear_capacity)
    return Eigen::VectorXd::Constant(1, axial - bolt.capacity);
  return Eigen::Vector3d(axial - bolt.capacity, shear - *bolt.shear_capacity,
                         -shear - *bolt.shear_capacity);
}

BlockPlanes block_planes(const BlockStrength& law) {
  const int n = law.planes;
  const double inscribed = std::cos(M_PI / n);
  const double sin_phi = law.criterion == BlockStrength::Criterion::tresca ? 0.0 : law.friction;
  const double sin_psi = law.criterion == BlockStrength::Criterion::tresca ? 0.0 : law.dilation;
  const double cos_phi = std::sqrt(1.0 - sin_phi * sin_phi);
  BlockPlanes planes;
  planes.a.resize(n, 3);
  planes.g.resize(n, 3);
  for (int k = 0; k < n; ++k) {
    // Plane k of the polygon inscribed in the circle of radius c cos(phi) - s sin(phi) around
    // ((s_x - s_y)/2, tau) = 0, with s = (s_x + s_y)/2 (tension positive).
    const double alpha = 2.0 * M_PI * k / n;
    const double ca = std::cos(alpha);
    const double sa = std::sin(alpha);
    planes.a.row(k) << 0.5 * ca + 0.5 * sin_phi * inscribed, -0.5 * ca + 0.5 * sin_phi * inscribed,
        sa;
    planes.g.row(k) << 0.5 * ca + 0.5 * sin_psi * inscribed, -0.5 * ca + 0.5 * sin_psi * inscribed,
        sa;
  }
  planes.strength = law.cohesion * cos_phi * inscribed;
  return planes;
}

namespace {

LocalYield joint_modes(const JointStrength& law, const PlasticState& s, const Eigen::VectorXd& r) {
  const double sigma_n = r(0);
  const double tau = r(1);
  const double tan_phi = law.friction.value(s.slip);
  LocalYield y;
  y.a.resize(3, 2);
  y.g.resize(3, 2);
  y.a << tan_phi, 1.0, tan_phi, -1.0, 1.0, 0.0;
  y.g << law.dilation, 1.0, law.dilation, -1.0, 1.0, 0.0;
  y.f = joint_values(law, s, sigma_n, tau);
  // Softening of c and tan(phi) with slip kappa_s = sum of both slip multipliers; of sigma_t
  // with the opening while the joint opens beyond its largest opening so far.
  y.h = Eigen::MatrixXd::Zero(3, 3);
  const double slip_h = law.cohesion.slope(s.slip) - sigma_n * law.friction.slope(s.slip);
  y.h.topLeftCorner<2, 2>().setConstant(slip_h);
  if (s.gap >= s.max_gap)
    y.h(2, 2) = law.tensile.slope(s.max_gap);
  return y;
}

LocalYield block_modes(const BlockStrength& law, const Eigen::VectorXd& sigma) {
  const BlockPlanes planes = block_planes(law);
  LocalYield y;
  y.f = planes.a * sigma - Eigen::VectorXd::Constant(planes.a.rows(), planes.strength);
  y.a = planes.a;
  y.g = planes.g;
  y.h = Eigen::MatrixXd::Zero(law.planes, law.planes);
  return y;
}

// Associated and perfectly plastic: the bar yields along its axis, the dowel across it.
LocalYield bolt_modes(const Bolt& bolt, const Eigen::VectorXd& r) {
  LocalYield y;
  const Eigen::Index n = bolt.shear_capacity ? 3 : 1;
  y.a = Eigen::MatrixXd::Zero(n, 2);
  y.a(0, 0) = 1.0;
  if (n == 3) {
    y.a(1, 1) = 1.0;
    y.a(2, 1) = -1.0;
  }
  y.g = y.a;
  y.f = bolt_values(bolt, r(0), r(1));
  y.h = Eigen::MatrixXd::Zero(n, n);
  return y;
}

}  // namespace

LocalYield linearize(const Model& model, const YieldPoint& p, const PlasticState& s,
                     const Eigen::VectorXd& stress) {
  if (p.is_interface())
    return joint_modes(*model.joint_materials[p.material].strength, s, stress);
  if (p.is_bolt())
    return bolt_modes(bolt_of(model, p), stress);
  return block_modes(*model.block_materials[p.material].strength, stress);
}

}  // namespace bimrock
